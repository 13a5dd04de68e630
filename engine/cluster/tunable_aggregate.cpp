#include "engine/cluster/tunable_aggregate.hpp"

#include <cmath>
#include <utility>

namespace aerobreak {

TunableAggregate centred_aggregate(std::vector<Vec3> position, std::vector<double> radius,
                                   GyrationConvention convention) {
  TunableAggregate a{std::move(position), std::move(radius), 0.0, 0.0, 0.0};
  Vec3 moment;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double m = a.radius[i] * a.radius[i] * a.radius[i];
    a.mass += m;
    moment += m * a.position[i];
    a.log_radius_sum += std::log(a.radius[i]);
  }
  const Vec3 centre = moment / a.mass;
  for (Vec3& x : a.position) x -= centre;
  a.gyration_radius = gyration_radius(a.position, a.radius, convention);
  return a;
}

}  // namespace aerobreak
