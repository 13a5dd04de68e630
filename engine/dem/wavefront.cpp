#include "engine/dem/wavefront.hpp"

#include <algorithm>
#include <cmath>

#include "engine/dem/simulation.hpp"
#include "engine/dem/simulation_force_pass.hpp"

namespace aerobreak {

std::int64_t Wavefront::advance(Simulation& sim, ParticleDrift& drift, std::int64_t left, double until) {
  const std::int64_t wanted = left > one_by_one_left_ ? 1 : std::min({deepest(sim), cap_, left});
  if (wanted <= 1) return 0;
  // Rebuilt early rather than run a wavefront of less than half the passes a fresh list allows;
  // not in a periodic box, where rebuilds wrap the positions (and so round them differently), nor
  // where the step is chosen at every rebuild: the steps would then differ from single steps.
  const bool early = !sim.settings_.periodic && !sim.chooser_ &&
                     2 * room(sim, drift.since_build2, drift, wanted) < room(sim, 0.0, drift, wanted);
  if (early) drift.since_build2 = std::numeric_limits<double>::infinity();
  sim.prepare_forces(drift);
  // The step changes with the next drift: that step's half kicks differ, so it runs alone.
  if (sim.switching_step()) return 0;
  // No pass after the first may be one at which a single step would choose the step again: the
  // pass k (k >= 1) whose clock, k steps on, reaches the end of the choice's hold.
  bool expires = false, reaches = false;
  const std::int64_t fits = room(sim, drift.since_build2, drift, wanted);
  const std::int64_t held = sim.steps_before(sim.choice_expires(), fits, expires);
  const std::int64_t depth = sim.steps_before(until, held, reaches);
  if (depth <= 1) return 0;
  if (const std::optional<ParticleDrift> next = run(sim, static_cast<int>(depth), depth < left && !reaches)) {
    drift = *next;
    cap_ = std::min(2 * cap_, deepest(sim));
    return depth;
  }
  one_by_one_left_ = left - depth;
  cap_ = std::max<std::int64_t>(2, depth / 2);
  return 0;
}

std::int64_t Wavefront::deepest(const Simulation& sim) const {
  // Van der Waals forces need a pass of their own between the pair forces and the integration.
  if (sim.spec_.van_der_waals || sim.particles_.size() < settings_.min_particles) return 1;
  return std::max(settings_.depth, 1);
}

// How many passes (at most `wanted`) can run on a list from which the particles have moved up to
// sqrt(since_build2): pass k sees the positions k drifts ahead, and each drift is taken to move a
// particle at most `margin` times as far as the last one moved any.
std::int64_t Wavefront::room(const Simulation& sim, double since_build2, const ParticleDrift& drift,
                             std::int64_t wanted) const {
  const double room = std::sqrt(sim.neighbors_->displacement_limit2()) - std::sqrt(since_build2);
  if (room < 0.0) return 0;
  const double per_pass = settings_.margin * std::sqrt(drift.last_step2);
  if (!(per_pass > 0.0)) return wanted;
  return std::min(wanted, 1 + static_cast<std::int64_t>(std::min(room / per_pass, static_cast<double>(wanted))));
}

// `depth` steps whose force passes run together (ContactForces::add_pair_forces). Each
// pass sums exactly as it would alone, and the run's sums take the passes in order, so the result
// is the one of `depth` single steps, to the last bit, provided the neighbour list held for
// every pass: if a pass has moved a particle out of the skin, the steps are undone (empty result).
std::optional<ParticleDrift> Wavefront::run(Simulation& sim, int depth, bool integrate_last) {
  sim.require_list_for_particles();
  save(sim);
  std::vector<Simulation::ForcePass> passes;
  std::vector<DissipationTally> pair_tally(static_cast<std::size_t>(depth));
  passes.reserve(static_cast<std::size_t>(depth));
  std::vector<ContactForces::Pass> list;
  for (int k = 0; k < depth; ++k) {
    passes.emplace_back(sim, true, k + 1 < depth || integrate_last, sim.steps_ + k + 1);
    list.push_back({{sim.pair_pool_, pair_tally[k], sim.pair_events_, nullptr}, passes.back()});
  }
  sim.add_pair_forces(0.0, list);
  // A pass after which the list had to be rebuilt, or the step chosen again, ran on a list or a
  // step that single steps would not have used.
  const double limit2 = sim.neighbors_->displacement_limit2();
  const double budget2 = sim.chooser_ ? sim.chooser_->budget2() : std::numeric_limits<double>::infinity();
  for (int k = 0; k + 1 < depth; ++k)
    if (passes[k].drift().since_build2 > limit2 || passes[k].drift().departure2 > budget2) {
      restore(sim);
      ++undone_;
      return std::nullopt;
    }
  for (int k = 0; k < depth; ++k) {
    sim.advance_clock();
    sim.tally_ += pair_tally[k];
    passes[k].book(sim.tally_, sim.external_work_);
  }
  steps_ += static_cast<std::uint64_t>(depth);
  return passes.back().drift();
}

void Wavefront::save(const Simulation& sim) {
  Checkpoint& c = checkpoint_;
  c.position = sim.particles_.position;
  c.velocity = sim.particles_.velocity;
  c.angular_velocity = sim.particles_.angular_velocity;
  c.pair_pool = sim.pair_pool_;
  c.wall_pool = sim.wall_pool_;
  c.wall_slots = sim.wall_slots_;
  c.pair_contacts = sim.neighbors_->pairs().contact;
  c.pair_events = sim.pair_events_;
  c.wall_events = sim.wall_events_;
}

void Wavefront::restore(Simulation& sim) const {
  const Checkpoint& c = checkpoint_;
  sim.particles_.position = c.position;
  sim.particles_.velocity = c.velocity;
  sim.particles_.angular_velocity = c.angular_velocity;
  sim.particles_.clear_forces();
  sim.pair_pool_ = c.pair_pool;
  sim.wall_pool_ = c.wall_pool;
  sim.wall_slots_ = c.wall_slots;
  sim.neighbors_->pairs().contact = c.pair_contacts;
  sim.pair_events_ = c.pair_events;
  sim.wall_events_ = c.wall_events;
}

}  // namespace aerobreak
