#include "engine/neighbor/periodic_box.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace aerobreak {
namespace {

// x shifted into [0, L); the number of lengths taken off is added to n, so that x = wrapped + n L.
double wrap_axis(double x, double length, std::int64_t& n) {
  const double shifts = std::floor(x / length);
  double wrapped = x - shifts * length;
  n += static_cast<std::int64_t>(shifts);
  // Round-off can leave x - floor(x/L) L equal to L (x slightly below a multiple of L).
  if (wrapped >= length) {
    wrapped -= length;
    ++n;
  }
  if (wrapped < 0.0) wrapped = 0.0;
  return wrapped;
}

}  // namespace

void PeriodicBox::validate() const {
  for (double edge : {length.x, length.y, length.z})
    if (!(edge > 0.0) || !std::isfinite(edge))
      throw std::invalid_argument("periodic box: every edge length must be positive and finite");
}

double PeriodicBox::shortest_edge() const { return std::min({length.x, length.y, length.z}); }

void PeriodicBox::require_single_image(double reach) const {
  if (!(2.0 * reach < shortest_edge()))
    throw std::invalid_argument("periodic box: the shortest edge (" + std::to_string(shortest_edge()) +
                                ") must exceed twice the interaction reach (" + std::to_string(reach) +
                                ", largest diameter + margin + skin)");
}

Vec3 PeriodicBox::minimum_image(const Vec3& d) const { return PeriodicSpace(*this)(d); }

Vec3 PeriodicBox::wrap(const Vec3& x, ImageCount& image) const {
  return {wrap_axis(x.x, length.x, image.x), wrap_axis(x.y, length.y, image.y), wrap_axis(x.z, length.z, image.z)};
}

Vec3 PeriodicBox::unwrap(const Vec3& x, const ImageCount& image) const {
  return {x.x + static_cast<double>(image.x) * length.x, x.y + static_cast<double>(image.y) * length.y,
          x.z + static_cast<double>(image.z) * length.z};
}

}  // namespace aerobreak
