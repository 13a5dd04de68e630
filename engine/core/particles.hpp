#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "engine/core/vec3.hpp"

namespace aerobreak {

// Spheres as structure-of-arrays: one contiguous array per field, indexed by particle.
// Forces and torques are accumulated by the force computation and read by the integrator.
struct Particles {
  std::vector<Vec3> position;
  std::vector<Vec3> velocity;
  std::vector<Vec3> angular_velocity;
  std::vector<Vec3> force;
  std::vector<Vec3> torque;
  std::vector<double> radius;
  std::vector<double> mass;
  std::vector<double> inertia;  // moment of inertia of a solid sphere, (2/5) m R^2
  std::vector<std::uint16_t> material;

  std::size_t size() const { return position.size(); }

  // Adds a solid sphere of the given radius and density at rest; returns its index.
  std::size_t add(const Vec3& at, double sphere_radius, double density, std::uint16_t material_index = 0);
  void clear_forces();
  void reserve(std::size_t n);
  // The mass-weighted mean position (the particles must not be empty).
  Vec3 centre_of_mass() const;
};

}  // namespace aerobreak
