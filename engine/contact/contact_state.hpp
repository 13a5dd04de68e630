#pragma once
#include <cstdint>

#include "engine/contact/contact_constants.hpp"
#include "engine/core/vec3.hpp"

namespace aerobreak {

// What one live contact carries from step to step: the springs' history and what its last
// evaluation found. The laws update it (ContactModel::evaluate); the energy the springs store
// follows from it (ContactModel::stored_energy), so the pair loop does not write it every step.
struct ContactHistory {
  Vec3 tangential_stretch;      // Mindlin spring (eqs 11-14)
  Vec3 rolling_displacement;    // xi (eq 18)
  double twist_angle = 0.0;     // phi (eq 17)
  double contact_radius = 0.0;  // a at the last evaluation
  double overlap = 0.0;         // delta at the last evaluation
  double damping_force = 0.0;   // normal damping force at the last evaluation (for its work)
};

// Everything one live contact remembers between steps. Contacts live in a pool, so their history
// survives neighbour-list rebuilds untouched.
struct ContactState : ContactHistory {
  ContactConstants constants;
  std::uint32_t i = 0;  // particle
  std::uint32_t j = 0;  // second particle, or the wall index for a wall contact
  bool with_wall = false;
};

}  // namespace aerobreak
