#include "engine/cluster/tunable_scaling_law.hpp"

#include <cmath>
#include <stdexcept>

namespace aerobreak {

double FractalLaw::gyration_radius(double primary_count, double primary_radius) const {
  return primary_radius * std::pow(primary_count / prefactor, 1.0 / fractal_dimension);
}

double primary_gyration_squared(double radius, GyrationConvention convention) {
  return convention == GyrationConvention::solid_spheres ? 0.6 * radius * radius : 0.0;
}

double gyration_radius(std::span<const Vec3> positions, std::span<const double> radii, GyrationConvention convention) {
  if (positions.empty() || positions.size() != radii.size()) {
    throw std::invalid_argument("gyration_radius: need one radius per position, at least one");
  }
  double mass = 0.0;
  Vec3 moment;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const double m = radii[i] * radii[i] * radii[i];
    mass += m;
    moment += m * positions[i];
  }
  const Vec3 centre = moment / mass;
  double sum = 0.0;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const double m = radii[i] * radii[i] * radii[i];
    sum += m * (norm2(positions[i] - centre) + primary_gyration_squared(radii[i], convention));
  }
  return std::sqrt(sum / mass);
}

double gyration_radius(const Cluster& cluster, GyrationConvention convention) {
  return gyration_radius(cluster.position, cluster.radius, convention);
}

double geometric_mean_radius(std::span<const double> radii) {
  if (radii.empty()) throw std::invalid_argument("geometric_mean_radius: no radii");
  double sum = 0.0;
  for (double r : radii) {
    if (!(r > 0.0)) throw std::invalid_argument("geometric_mean_radius: non-positive radius");
    sum += std::log(r);
  }
  return std::exp(sum / static_cast<double>(radii.size()));
}

double centre_distance_squared(double m1, double rg1, double m2, double rg2, double rg) {
  const double m = m1 + m2;
  return m * m / (m1 * m2) * rg * rg - m / m2 * rg1 * rg1 - m / m1 * rg2 * rg2;
}

}  // namespace aerobreak
