#include "engine/core/particles.hpp"

#include <algorithm>
#include <numbers>

namespace aerobreak {

std::size_t Particles::add(const Vec3& at, double sphere_radius, double density, std::uint16_t material_index) {
  const double m = density * 4.0 / 3.0 * std::numbers::pi * sphere_radius * sphere_radius * sphere_radius;
  position.push_back(at);
  velocity.push_back({});
  angular_velocity.push_back({});
  force.push_back({});
  torque.push_back({});
  radius.push_back(sphere_radius);
  mass.push_back(m);
  inertia.push_back(0.4 * m * sphere_radius * sphere_radius);
  material.push_back(material_index);
  return position.size() - 1;
}

void Particles::clear_forces() {
  std::fill(force.begin(), force.end(), Vec3{});
  std::fill(torque.begin(), torque.end(), Vec3{});
}

Vec3 Particles::centre_of_mass() const {
  Vec3 centre;
  double total = 0.0;
  for (std::size_t i = 0; i < size(); ++i) {
    centre += mass[i] * position[i];
    total += mass[i];
  }
  return centre / total;
}

void Particles::reserve(std::size_t n) {
  position.reserve(n);
  velocity.reserve(n);
  angular_velocity.reserve(n);
  force.reserve(n);
  torque.reserve(n);
  radius.reserve(n);
  mass.reserve(n);
  inertia.reserve(n);
  material.reserve(n);
}

}  // namespace aerobreak
