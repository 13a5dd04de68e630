#pragma once
#include <vector>

#include "engine/contact/model_spec.hpp"
#include "engine/core/material_table.hpp"
#include "engine/core/particles.hpp"
#include "engine/dem/contact_forces.hpp"
#include "engine/dem/wall.hpp"

namespace aerobreak {

// The automatic time step and how it was reached (recorded with every run).
struct TimeStepEstimate {
  double time_step = 0.0;
  double period = 0.0;            // shortest contact oscillation period found
  double stiffness = 0.0;         // the stiffness that sets it (normal, or tangential x 7/2)
  double mass = 0.0;              // the reduced mass that sets it
  double overlap = 0.0;           // deepest overlap the contact can reach
  double steps_per_period = 0.0;  // the safety factor: period / time_step
};

// The stiffest contact the run can reach: each pair of extreme radii (and each wall) is loaded
// by the kinetic energy of the largest relative speed (2 v_max between particles, v_max against
// a wall) plus twice its adhesion work 2 F_c delta_c; its normal stiffness dF/ddelta there and at
// equilibrium, its tangential stiffness 8 G* a (times 7/2, the mass factor of a rolling sphere's
// tangential mode) and, with rolling resistance, its rolling mode give the period 2 pi sqrt(m*/k). The step is the shortest period
// divided by steps_per_period (default 50, well inside the report's dt < sqrt(m/k_n)).
TimeStepEstimate recommend_time_step(const Particles& particles, const MaterialTable& materials,
                                     const std::vector<Wall>& walls, const ContactModelSpec& spec, double max_speed,
                                     double steps_per_period = 50.0);

}  // namespace aerobreak
