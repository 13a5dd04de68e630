#pragma once
#include <vector>

#include "engine/contact/model_spec.hpp"
#include "engine/core/material_table.hpp"
#include "engine/core/particles.hpp"
#include "engine/dem/contact_forces.hpp"
#include "engine/dem/wall.hpp"

namespace aerobreak {

// What the automatic time step must resolve (docs/MODEL.md 9.2).
struct TimeStepFactors {
  // Steps per shortest contact oscillation period (well inside the report's dt < sqrt(m/k_n)).
  double steps_per_period = 50.0;
  // Steps in which the fastest approach crosses the break overlap delta_b, the tensile range
  // between touching and letting go (JKR: delta_c, eq 3, or 0.48 delta_c by the force rule), so
  // that the energy lost in the adhesion loop is right. 0: not resolved.
  double steps_per_break_overlap = 10.0;
};

// Which of the two conditions set the step.
enum class TimeStepLimit { contact_period, break_overlap };

// The automatic time step and how it was reached (recorded with every run).
struct TimeStepEstimate {
  double time_step = 0.0;
  TimeStepLimit limit = TimeStepLimit::contact_period;
  double period = 0.0;                   // shortest contact oscillation period found
  double stiffness = 0.0;                // the stiffness that sets it (normal, or tangential x 7/2)
  double mass = 0.0;                     // the reduced mass that sets it
  double overlap = 0.0;                  // deepest overlap the contact can reach
  double steps_per_period = 0.0;         // the factor the period is divided by
  double crossing_time = 0.0;            // shortest break overlap / approach speed (0: no tensile range)
  double break_overlap = 0.0;            // the delta_b that sets it
  double approach_speed = 0.0;           // the approach speed that sets it
  double steps_per_break_overlap = 0.0;  // the factor the crossing time is divided by
};

const char* time_step_limit_name(TimeStepLimit limit);

// The step resolves every contact the run can reach. Each pair of extreme radii (and each wall)
// is probed at the fastest approach speed (2 v_max between particles, v_max against a wall):
// (1) loaded by that speed's kinetic energy plus twice its adhesion work 2 F_c delta_c, its
// normal stiffness dF/ddelta there and at equilibrium, its tangential stiffness 8 G* a (times
// 7/2, the mass factor of a rolling sphere's tangential mode) and, with rolling resistance, its
// rolling mode give the period 2 pi sqrt(m*/k); (2) its break overlap over the approach speed
// gives the time in which the contact crosses its tensile range. The step is the shortest period
// over factors.steps_per_period or the shortest crossing time over factors.steps_per_break_overlap,
// whichever is shorter.
TimeStepEstimate recommend_time_step(const Particles& particles, const MaterialTable& materials,
                                     const std::vector<Wall>& walls, const ContactModelSpec& spec, double max_speed,
                                     const TimeStepFactors& factors = {});

// The shortest break overlap delta_b of a contact the run can make between particles and with a
// wall (the same probes as recommend_time_step: spheres of extreme radius, every material pair);
// 0 where no such contact has a tensile range (Hertz, DMT, a single particle, no wall). With each,
// the largest adhesion speed (2 F_c delta_c / m*)^(1/2) of those contacts, the speed whose kinetic
// energy is the adhesion loop's scale (the sticking speed is 0.97 of it by the displacement rule,
// 0.68 by the force rule; docs/MODEL.md 3.4).
struct BreakOverlaps {
  double pair = 0.0;
  double wall = 0.0;
  double pair_adhesion_speed = 0.0;
  double wall_adhesion_speed = 0.0;
};
BreakOverlaps shortest_break_overlaps(const Particles& particles, const MaterialTable& materials,
                                      const std::vector<Wall>& walls, const ContactModelSpec& spec);

}  // namespace aerobreak
