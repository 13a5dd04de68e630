#include "engine/impact/settle.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "engine/dem/simulation.hpp"
#include "engine/impact/fate_rule.hpp"

namespace aerobreak {
namespace {

std::string describe_fragment(std::size_t k, const Fragment& f) {
  return "fragment " + std::to_string(k + 1) + " (" + std::to_string(f.size) + " primar" + (f.size == 1 ? "y" : "ies") +
         ")";
}

std::string number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", x);
  return buffer;
}

std::uint64_t all_events(const Simulation& simulation) {
  return simulation.pair_events().made + simulation.pair_events().broken + simulation.wall_events().made +
         simulation.wall_events().broken;
}

std::uint64_t wall_events(const Simulation& simulation) {
  return simulation.wall_events().made + simulation.wall_events().broken;
}

}  // namespace

std::string unsettled_reason(const std::vector<Fragment>& fragments, const std::vector<Vec3>& mean_velocity,
                             const std::vector<double>& lowest_gap_before, const Vec3& wall_normal, double rest_speed,
                             bool deposit_pairs) {
  const Vec3 n = wall_normal / norm(wall_normal);
  for (std::size_t k = 0; k < fragments.size(); ++k) {
    const Fragment& f = fragments[k];
    const double mean_normal = dot(mean_velocity[k], n);
    if (f.on_wall()) {
      if (std::abs(mean_normal) > rest_speed)
        return describe_fragment(k, f) + " touches the wall and is not at rest (mean normal speed " +
               number(mean_normal) + ", rest below " + number(rest_speed) + ")";
    } else if (!(mean_normal > 0.0 && f.normal_velocity > 0.0)) {
      return describe_fragment(k, f) + " is off the wall but not moving away from it (normal speed " +
             number(f.normal_velocity) + ")";
    } else if (!(f.lowest_gap > lowest_gap_before[k])) {
      return describe_fragment(k, f) + " is moving away from the wall but its lowest point is not";
    }
  }
  // Two fragments can still meet if their centres approach and, moving on as they do, would pass
  // closer than their bounding spheres allow. Fragments both resting on the wall are left out
  // unless asked for.
  for (std::size_t a = 0; a < fragments.size(); ++a)
    for (std::size_t b = a + 1; b < fragments.size(); ++b) {
      if (!deposit_pairs && fragments[a].on_wall() && fragments[b].on_wall()) continue;
      const Vec3 separation = fragments[b].centre_of_mass - fragments[a].centre_of_mass;
      const Vec3 relative = mean_velocity[b] - mean_velocity[a];
      const double approach = dot(separation, relative);
      if (approach >= 0.0) continue;
      const Vec3 miss = separation - (approach / norm2(relative)) * relative;
      const double reach = fragments[a].bounding_radius + fragments[b].bounding_radius;
      if (norm2(miss) <= reach * reach)
        return describe_fragment(a, fragments[a]) + " and " + describe_fragment(b, fragments[b]) +
               " are approaching each other";
    }
  return {};
}

std::string outcome_open_reason(const std::vector<Fragment>& fragments, const std::vector<Vec3>& mean_velocity,
                                const std::vector<double>& lowest_gap_before, const Vec3& wall_normal,
                                double rest_speed, const OutcomeThresholds& thresholds, bool unbroken) {
  // Before the quiet rule, which waits until nothing moves, the deposit's pieces may still creep
  // into each other: they are tested for meeting too.
  std::string reason = unsettled_reason(fragments, mean_velocity, lowest_gap_before, wall_normal, rest_speed, true);
  if (!reason.empty()) return reason;
  if (unbroken) return {};
  const Classification c = classify(fates_of(fragments, mean_velocity, wall_normal), true, thresholds);
  if (c.outcome != ImpactOutcome::break_up)
    return "the state is a " + to_string(c.outcome) + ", not a break-up, and contacts broke during the window";
  double mass = 0.0;
  for (const Fragment& f : fragments) mass += f.mass;
  for (std::size_t k = 0; k < fragments.size(); ++k)
    if (fragments[k].on_wall() && fragments[k].mass >= thresholds.bounce_share * mass)
      return describe_fragment(k, fragments[k]) + " on the wall could still leave as a bounce";
  return {};
}

std::string to_string(SettleRule rule) {
  switch (rule) {
    case SettleRule::quiet:
      return "quiet";
    case SettleRule::outcome_fixed:
      return "outcome_fixed";
    case SettleRule::fates_fixed:
      return "fates_fixed";
  }
  return "quiet";
}

SettleMonitor::SettleMonitor(double quiet_window, double rest_speed, OutcomeThresholds thresholds,
                             bool outcome_fixed_rule, bool follow_rigid_turn)
    : quiet_window_(quiet_window),
      rest_speed_(rest_speed),
      thresholds_(thresholds),
      outcome_fixed_rule_(outcome_fixed_rule),
      follow_rigid_turn_(follow_rigid_turn) {
  if (!(quiet_window > 0.0)) throw std::invalid_argument("settle: quiet_window must be > 0");
  if (!(rest_speed >= 0.0)) throw std::invalid_argument("settle: rest_speed must be >= 0");
}

SettleMonitor::Window SettleMonitor::open_window(const Simulation& simulation, bool with_deposit) const {
  Window w;
  w.start = simulation.time();
  w.positions = simulation.particles().position;
  w.events = with_deposit ? wall_events(simulation) : all_events(simulation);
  w.bonds_broken = simulation.pair_events().broken;
  if (!with_deposit) return w;
  // The primaries of the fragments touching the wall, and their contacts among themselves.
  const FragmentAnalysis now = find_fragments(simulation);
  std::vector<char> on_wall(now.fragment_of.size(), 0);
  for (std::uint32_t i = 0; i < now.fragment_of.size(); ++i)
    if (now.fragments[now.fragment_of[i]].on_wall()) {
      on_wall[i] = 1;
      w.deposit.push_back(i);
    }
  simulation.contacts().for_each([&](const ContactState& c) {
    if (!c.with_wall && on_wall[c.i] && on_wall[c.j])
      w.deposit_contacts.emplace_back(std::min(c.i, c.j), std::max(c.i, c.j));
  });
  std::sort(w.deposit_contacts.begin(), w.deposit_contacts.end());
  return w;
}

SettleMonitor::Judgement SettleMonitor::judge(const Simulation& simulation, const Window& window) const {
  // Velocities are those of each fragment's present primaries, from their displacement over the
  // window: a fragment stuck to the wall still vibrates.
  Judgement j;
  j.fragments = find_fragments(simulation);
  const Particles& p = simulation.particles();
  const Wall wall = simulation.walls().empty() ? Wall{} : simulation.walls().front();
  j.wall_normal = wall.normal / norm(wall.normal);
  const std::size_t count = j.fragments.fragments.size();
  j.mean_velocity.assign(count, Vec3{});
  j.lowest_gap_before.assign(count, std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < p.size(); ++i) {
    const std::uint32_t k = j.fragments.fragment_of[i];
    j.mean_velocity[k] += p.mass[i] * (p.position[i] - window.positions[i]);
    j.lowest_gap_before[k] =
        std::min(j.lowest_gap_before[k], dot(window.positions[i] - wall.point, j.wall_normal) - p.radius[i]);
  }
  const double elapsed = simulation.time() - window.start;
  for (std::size_t k = 0; k < count; ++k)
    j.mean_velocity[k] = j.mean_velocity[k] / (j.fragments.fragments[k].mass * elapsed);
  return j;
}

void SettleMonitor::settle(const Simulation& simulation, SettleRule rule, const Window& window) {
  settled_ = true;
  rule_ = rule;
  settled_at_ = simulation.time();
  since_ = window.start;
}

bool SettleMonitor::judge_quiet(const Simulation& simulation) {
  ++judgements_;
  Judgement j = judge(simulation, quiet_);
  last_reason_ =
      unsettled_reason(j.fragments.fragments, j.mean_velocity, j.lowest_gap_before, j.wall_normal, rest_speed_);
  judged_ = std::move(j.fragments);
  judged_mean_velocity_ = std::move(j.mean_velocity);
  since_ = quiet_.start;
  if (last_reason_.empty()) settle(simulation, SettleRule::quiet, quiet_);
  return settled_;
}

bool SettleMonitor::judge_outcome_fixed(const Simulation& simulation) {
  const Window now = open_window(simulation, true);
  if (now.events != fixed_.events || now.deposit != fixed_.deposit || now.deposit_contacts != fixed_.deposit_contacts)
    return false;
  ++judgements_;
  Judgement j = judge(simulation, fixed_);
  const std::string reason =
      outcome_open_reason(j.fragments.fragments, j.mean_velocity, j.lowest_gap_before, j.wall_normal, rest_speed_,
                          thresholds_, now.bonds_broken == fixed_.bonds_broken);
  if (!reason.empty()) return false;
  // A state that is not a break-up stands on its fragments' staying off the wall: one tumbling
  // fast enough could still swing back and be pushed off again, with another restitution.
  const Classification c = classify(fates_of(j.fragments.fragments, j.mean_velocity, j.wall_normal), true, thresholds_);
  if (c.outcome != ImpactOutcome::break_up && !swing_back_reason(simulation, follow_rigid_turn_).empty()) return false;
  last_reason_.clear();
  judged_ = std::move(j.fragments);
  judged_mean_velocity_ = std::move(j.mean_velocity);
  settle(simulation, SettleRule::outcome_fixed, fixed_);
  return true;
}

bool SettleMonitor::judge_fates_fixed(const Simulation& simulation) {
  FatesJudgement j = judge_fates(simulation, last_positions_, last_time_);
  last_positions_ = simulation.particles().position;
  last_time_ = simulation.time();
  last_fates_reason_ = std::move(j.reason);
  if (!last_fates_reason_.empty()) return false;
  ++judgements_;
  last_reason_.clear();
  judged_ = std::move(j.fragments);
  judged_mean_velocity_ = std::move(j.velocities);
  Window now;
  now.start = simulation.time();
  settle(simulation, SettleRule::fates_fixed, now);
  return true;
}

std::string SettleMonitor::open_reason(const Simulation& simulation) const {
  std::string reason;
  if (all_events(simulation) != quiet_.events)
    reason = "contacts were still made or broken after t = " + number(quiet_.start);
  else if (quiet_opened_by_change_)
    reason = "contacts were still made or broken until about t = " + number(quiet_.start) +
             ", less than a quiet window before the end";
  else
    reason = "the quiet window that began at t = " + number(quiet_.start) + " had not ended";
  if (!last_reason_.empty()) reason += "; at the last judgement " + last_reason_;
  if (!last_fates_reason_.empty()) reason += "; the fates-fixed rule's last objection: " + last_fates_reason_;
  return reason;
}

bool SettleMonitor::update(const Simulation& simulation) {
  if (settled_) return true;
  if (!started_) {
    started_ = true;
    quiet_ = open_window(simulation, false);
    fixed_ = open_window(simulation, true);
    since_ = quiet_.start;
    last_positions_ = simulation.particles().position;
    last_time_ = simulation.time();
    return false;
  }
  // The quiet rule first: when both would pass, the run is settled in the plain sense.
  if (all_events(simulation) != quiet_.events) {
    quiet_ = open_window(simulation, false);
    quiet_opened_by_change_ = true;
  } else if (simulation.time() - quiet_.start >= quiet_window_) {
    if (judge_quiet(simulation)) return true;
    quiet_ = open_window(simulation, false);
    quiet_opened_by_change_ = false;
  }
  if (outcome_fixed_rule_ && simulation.time() - fixed_.start >= quiet_window_) {
    if (judge_outcome_fixed(simulation)) return true;
    fixed_ = open_window(simulation, true);
  }
  return outcome_fixed_rule_ && judge_fates_fixed(simulation);
}

}  // namespace aerobreak
