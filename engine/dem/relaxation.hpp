#pragma once
#include <cstdint>
#include <vector>

#include "engine/contact/model_spec.hpp"
#include "engine/core/material.hpp"
#include "engine/core/particles.hpp"

namespace aerobreak {

struct RelaxationSettings {
  // Each particle i is judged on its own scales, those of a contact between two spheres like it:
  // its pull-off force F_c,i (eq 5) and bond energy E_i = F_c,i a0,i^2 / R*_i (eqs 4, 5).
  double bond_gap = 1e-6;            // surfaces closer than this (in d) start bonded
  double kinetic_tolerance = 1e-12;  // converged when the mean of (kinetic energy of i / E_i) < this
  double force_tolerance = 1e-6;     // ... and every net force on i < this x F_c,i
  std::int64_t max_steps = 5'000'000;
};

struct RelaxationResult {
  Particles particles;  // relaxed positions, zero velocities
  std::int64_t steps = 0;
  bool converged = false;
  double kinetic_per_particle = 0.0;  // at the end: mean of (kinetic energy of i / E_i)
  double largest_force = 0.0;         // at the end: largest (net force on i / F_c,i)
  std::size_t contacts = 0;           // particle-particle contacts at the end
  std::uint64_t contacts_broken = 0;  // during relaxation (0 for a cluster that holds together)
};

// Brings a cluster built at touching distance to mechanical equilibrium (docs/MODEL.md 11.1):
// contacts at their equilibrium overlap, internal kinetic energy ~0. It runs the model's normal
// law only (so no tangential, rolling or twisting spring is left stretched), with Tsuji damping
// that is critical about equilibrium for every contact whatever its size (so polydisperse clusters
// relax too), and a drag on every particle, which also stills the floppy modes of the open
// fractal network that contact damping cannot reach. docs/MODEL.md section 11.1.
RelaxationResult relax_cluster(Particles particles, const std::vector<Material>& materials,
                               const ContactModelSpec& model, const RelaxationSettings& settings = {});

}  // namespace aerobreak
