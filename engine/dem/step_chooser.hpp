#pragma once
#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

#include "engine/core/particles.hpp"
#include "engine/dem/time_step.hpp"
#include "engine/dem/wall.hpp"
#include "engine/neighbor/pair_list.hpp"

namespace aerobreak {

// The steps a run has taken: the shortest and longest, how many under each limit of the automatic
// step (a fixed step counts as the contact period's) and how often the step was chosen.
struct StepHistory {
  double shortest = 0.0;
  double longest = 0.0;
  std::int64_t steps = 0;
  double time = 0.0;  // simulated time of these steps
  std::int64_t contact_period_steps = 0;
  std::int64_t break_overlap_steps = 0;
  std::uint64_t choices = 0;

  void record(double dt, TimeStepLimit limit) {
    shortest = steps == 0 ? dt : std::min(shortest, dt);
    longest = std::max(longest, dt);
    ++steps;
    time += dt;
    ++(limit == TimeStepLimit::break_overlap ? break_overlap_steps : contact_period_steps);
  }
  double mean() const { return steps > 0 ? time / static_cast<double>(steps) : 0.0; }
};

// The time step chosen again during a run from the speeds of the moment (docs/MODEL.md 9.2): a
// contact's adhesion loop needs steps_per_break_overlap steps in the time its approach speed u
// takes to cross the break overlap, dt <= delta_b / (f u), and the contact period bounds the step
// whatever the speeds (`cap`). A choice looks at the drift velocities: of each listed pair (no
// other pair can touch before the neighbour list is rebuilt) the relative velocity along the line
// of centres and across it, of each particle that can reach a wall with a tensile range before
// then its normal velocity. It takes the step for the fastest approach these allow while the line
// of centres turns by at most `turn` radians, plus a headroom, and keeps as its budget how far any
// drift velocity may still depart from the velocity it had at the choice before the step is too
// long; the simulation chooses again as soon as one departs further, when the choice's hold (the
// time in which no line of centres can turn further) has passed, and at every rebuild of the list.
class StepChooser {
 public:
  struct Choice {
    double time_step = 0.0;
    TimeStepLimit limit = TimeStepLimit::contact_period;
    double pair_speed = 0.0;  // fastest approach of a listed pair while its line of centres turns by `turn`
    double wall_speed = 0.0;  // fastest normal speed of a particle within reach of a wall
    double hold = std::numeric_limits<double>::infinity();  // simulated time the choice holds at most
  };

  // `headroom`: the share of the fastest speed found that the velocities may change by before the
  // next choice, at least.
  StepChooser(double cap, BreakOverlaps overlaps, double steps_per_break_overlap, double headroom = 0.15,
              double turn = 0.1);

  // Chooses the step for the drifts to come. `built_at` and `skin` are the neighbour list's: until
  // its next rebuild every particle stays within skin/2 of where it was built. `current` is the
  // step now (0: none yet): it is kept while it is short enough and the speeds allow less than
  // `growth` times it and less than the cap. A changing step costs accuracy (velocity Verlet conserves a shadow of the
  // energy that depends on the step, so each change moves the energy by a share of order
  // (w dt)^2): the step changes seldom, shorter at once when it must, longer only by leaps.
  Choice choose(const Particles& particles, const PairList& pairs, const std::vector<Wall>& walls,
                const std::vector<Vec3>& built_at, double skin, double current = 0.0);
  static constexpr double growth = 2.0;

  // The squared departure of a drift velocity from the one of the last choice past which the step
  // must be chosen again (infinite where no speed can make it too long).
  double budget2() const { return budget2_; }
  // The particles' velocities at the last choice.
  const std::vector<Vec3>& reference() const { return reference_; }
  double cap() const { return cap_; }

 private:
  struct PairSpeeds {
    double approach = 0.0;                                     // largest |along| + turn |across| of a listed pair
    double relative = 0.0;                                     // largest relative speed
    double closest = std::numeric_limits<double>::infinity();  // smallest distance between centres
  };
  PairSpeeds pair_speeds(const Particles& particles, const PairList& pairs) const;
  double fastest_wall_speed(const Particles& particles, const std::vector<Wall>& walls,
                            const std::vector<Vec3>& built_at, double skin) const;
  // The step that resolves the break overlaps at these approach speeds (infinite if none has to).
  double crossing_step(double pair_speed, double wall_speed) const;

  double cap_;
  BreakOverlaps overlaps_;
  double steps_per_break_overlap_;
  double headroom_;
  double turn_;
  double budget2_ = std::numeric_limits<double>::infinity();
  std::vector<Vec3> reference_;
};

}  // namespace aerobreak
