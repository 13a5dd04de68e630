#pragma once
#include "engine/core/material.hpp"

namespace aerobreak {

// Constants of one contact, fixed when the contact forms (radii, masses and materials do not
// change during a run). The normal law fills the adhesion fields; every other law only reads.
struct ContactConstants {
  double radius = 0.0;            // R* = Ri Rj / (Ri + Rj); R_i for a wall
  double mass = 0.0;              // m* = mi mj / (mi + mj); m_i for a wall
  double modulus = 0.0;           // E*
  double shear = 0.0;             // G*
  double work_of_adhesion = 0.0;  // w

  // Filled by the normal law:
  double hertz_coefficient = 0.0;   // K = (4/3) E* sqrt(R*): Hertz force K delta^(3/2)
  double equilibrium_radius = 0.0;  // a0, eq 4 (JKR reference radius; 0 without adhesion)
  double pull_off_force = 0.0;      // F_c, eq 5 (JKR), pi gamma d analogue (DMT), 0 (Hertz)
  double critical_overlap = 0.0;    // delta_c, eq 3
  double break_overlap = 0.0;       // the contact ends when delta < -break_overlap
  double overlap_scale = 1.0;       // delta times this is the overlap the law solves for (JKR: R*/a0^2)

  bool operator==(const ContactConstants&) const = default;
};

// What the normal law hands to the other slots (docs/ARCHITECTURE.md, "The engine": explicit, no shared state).
struct NormalResponse {
  double force = 0.0;           // elastic normal force, > 0 repulsive
  double contact_radius = 0.0;  // a
  // Load that sets the friction and twisting limits, >= 0: F_n + 2 F_c for JKR (eq 14), the
  // Hertz part F_n + F_c for DMT, F_n for Hertz.
  double coulomb_load = 0.0;
  double energy = 0.0;                     // elastic energy stored in the normal deformation
  double radius_ratio_three_halves = 0.0;  // (a/a0)^(3/2), for the rolling stiffness (eq 18)
};

}  // namespace aerobreak

namespace aerobreak {

// A contact's geometry and material before the normal law completes it.
inline ContactConstants unfinished_constants(double radius, double mass, const PairMaterial& material) {
  ContactConstants c;
  c.radius = radius;
  c.mass = mass;
  c.modulus = material.modulus;
  c.shear = material.shear;
  c.work_of_adhesion = material.work_of_adhesion;
  return c;
}

// Two spheres (docs/MODEL.md section 2: R* = RiRj/(Ri+Rj), m* likewise) of the given pair of materials.
inline ContactConstants sphere_pair_constants(double radius_i, double mass_i, double radius_j, double mass_j,
                                              const PairMaterial& material) {
  return unfinished_constants(radius_i * radius_j / (radius_i + radius_j), mass_i * mass_j / (mass_i + mass_j),
                              material);
}

// A wall is a sphere of infinite radius and mass: R* = R_i, m* = m_i.
inline ContactConstants sphere_wall_constants(double radius_i, double mass_i, const PairMaterial& material) {
  return unfinished_constants(radius_i, mass_i, material);
}

}  // namespace aerobreak
