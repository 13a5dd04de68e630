#include "engine/dem/step_chooser.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace aerobreak {

StepChooser::StepChooser(double cap, BreakOverlaps overlaps, double steps_per_break_overlap, double headroom,
                         double turn)
    : cap_(cap),
      overlaps_(overlaps),
      steps_per_break_overlap_(steps_per_break_overlap),
      headroom_(headroom),
      turn_(turn) {
  if (!(cap > 0.0) || !std::isfinite(cap)) throw std::invalid_argument("step chooser: the cap must be > 0");
  if (!(steps_per_break_overlap > 0.0))
    throw std::invalid_argument("step chooser: steps_per_break_overlap must be > 0");
  if (!(headroom >= 0.0)) throw std::invalid_argument("step chooser: the headroom must be >= 0");
  if (!(turn > 0.0 && turn < 1.0)) throw std::invalid_argument("step chooser: the turn must be in (0, 1)");
}

// Every pair that can touch, or let go, before the list is rebuilt is listed. Its approach rate
// (the overlap's rate of change) at a later time is -dv(t).n(t); with dv(t) within 2 budget of dv
// now, and n(t) within `turn` radians of n now, it is at most a + turn |dv x n| + 2 budget, where
// a = |dv.n| for a pair in contact (it may let go, separating) and a = max(-dv.n, 0) for one not
// in contact (only closing makes a contact: a pair moving apart would first have to turn back).
StepChooser::PairSpeeds StepChooser::pair_speeds(const Particles& p, const PairList& pairs) const {
  PairSpeeds s;
  if (!(overlaps_.pair > 0.0)) return s;
  double relative2 = 0.0, closest2 = std::numeric_limits<double>::infinity();
  for (std::uint32_t i = 0; i < pairs.particles(); ++i)
    for (std::uint32_t k = pairs.row_start[i]; k < pairs.row_start[i + 1]; ++k) {
      const std::uint32_t j = pairs.neighbor[k];
      const Vec3 dv = p.velocity[j] - p.velocity[i];
      const Vec3 r = p.position[j] - p.position[i];
      const double r2 = norm2(r);
      const double distance = std::sqrt(r2);
      const double opening = distance > 0.0 ? dot(dv, r) / distance : 0.0;  // > 0: moving apart
      const double along = pairs.contact[k] >= 0 ? std::abs(opening) : std::max(-opening, 0.0);
      const double across = distance > 0.0 ? norm(cross(dv, r)) / distance : norm(dv);
      s.approach = std::max(s.approach, along + turn_ * across);
      relative2 = std::max(relative2, norm2(dv));
      closest2 = std::min(closest2, r2);
    }
  s.relative = std::sqrt(relative2);
  s.closest = std::sqrt(closest2);
  return s;
}

// A particle can make or break a wall contact before the next rebuild only if its surface is
// within the break overlap of the wall plus how far it may still move: skin/2 from where the list
// was built, so up to skin/2 + its displacement since then from here. The wall's normal is fixed,
// so the normal velocity now plus the budget bounds its normal speed until then.
double StepChooser::fastest_wall_speed(const Particles& p, const std::vector<Wall>& walls,
                                       const std::vector<Vec3>& built_at, double skin) const {
  if (!(overlaps_.wall > 0.0)) return 0.0;
  double fastest = 0.0;
  for (const Wall& wall : walls) {
    if (!wall.adhesive) continue;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double reach = overlaps_.wall + 0.5 * skin + norm(p.position[i] - built_at[i]);
      if (wall.gap(p.position[i]) - p.radius[i] <= reach)
        fastest = std::max(fastest, std::abs(dot(p.velocity[i], wall.normal)));
    }
  }
  return fastest;
}

// Approaches slower than a contact's adhesion speed are resolved as if at that speed: the error of
// an event is a share of the loop's energy, of order F_c delta_c, set by u dt / delta_b, and it
// counts against kinetic energies of that order: near the sticking speed, where a restitution
// hangs on the small energy left after the loop, the step is the one the impact speed gave.
double StepChooser::crossing_step(double pair_speed, double wall_speed) const {
  double step = std::numeric_limits<double>::infinity();
  if (overlaps_.pair > 0.0)
    step = overlaps_.pair / (steps_per_break_overlap_ * std::max(pair_speed, overlaps_.pair_adhesion_speed));
  if (overlaps_.wall > 0.0)
    step = std::min(step,
                    overlaps_.wall / (steps_per_break_overlap_ * std::max(wall_speed, overlaps_.wall_adhesion_speed)));
  return step;
}

// The step for the approaches found plus the headroom h = headroom x the fastest of them: a
// listed pair approaches at most at u_pair + 2h before the next choice (each of its two velocities
// may depart by h), a particle a wall at most at u_wall + h. The budget is then the
// largest departure this step still resolves, at least h. The choice holds while no line of
// centres can have turned by more than `turn`: it turns at most at (|dv| + 2 budget) / |r|, and
// |r| stays above 0.9 of the closest centres now (they approach by at most turn |r| in that time).
StepChooser::Choice StepChooser::choose(const Particles& p, const PairList& pairs, const std::vector<Wall>& walls,
                                        const std::vector<Vec3>& built_at, double skin, double current) {
  Choice c;
  const PairSpeeds pair = pair_speeds(p, pairs);
  c.pair_speed = pair.approach;
  c.wall_speed = fastest_wall_speed(p, walls, built_at, skin);
  const double h = headroom_ * std::max(c.pair_speed, c.wall_speed);
  const double crossing = crossing_step(c.pair_speed + 2.0 * h, c.wall_speed + h);
  const double allowed = std::min(cap_, crossing);
  // Kept while the speeds allow less than `growth` times it, unless they allow the cap: a step
  // within a leap of the cap would otherwise stay below it for the rest of the run.
  const bool keep = current > 0.0 && allowed >= current && allowed < growth * current && allowed < cap_;
  c.time_step = keep ? current : allowed;
  c.limit = c.time_step < cap_ ? TimeStepLimit::break_overlap : TimeStepLimit::contact_period;

  double budget = std::numeric_limits<double>::infinity();
  const double resolved = 1.0 / (steps_per_break_overlap_ * c.time_step);  // speed per unit break overlap
  if (overlaps_.pair > 0.0)
    budget = 0.5 * (std::max(overlaps_.pair * resolved, overlaps_.pair_adhesion_speed) - c.pair_speed);
  if (overlaps_.wall > 0.0)
    budget = std::min(budget, std::max(overlaps_.wall * resolved, overlaps_.wall_adhesion_speed) - c.wall_speed);
  budget = std::max(budget, h);
  budget2_ = budget * budget;
  if (pair.relative > 0.0 || budget < std::numeric_limits<double>::infinity())
    c.hold = turn_ * 0.9 * pair.closest / (pair.relative + 2.0 * budget);
  reference_ = p.velocity;
  return c;
}

}  // namespace aerobreak
