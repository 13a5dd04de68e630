#include "engine/impact/run_observers.hpp"

#include <algorithm>
#include <stdexcept>

#include "engine/dem/simulation.hpp"
#include "engine/impact/fragments.hpp"
#include "engine/impact/settle.hpp"

namespace aerobreak {

bool StepObserver::due(const Simulation& simulation) const {
  return next_step() <= simulation.step_count() || next_time() <= simulation.time();
}

bool run_observed(Simulation& simulation, double time_limit, const std::vector<StepObserver*>& observers) {
  while (simulation.time() < time_limit) {
    std::int64_t step = std::numeric_limits<std::int64_t>::max();
    double until = time_limit;
    for (const StepObserver* o : observers) {
      if (o->due(simulation)) throw std::logic_error("run_observed: an observer asks for a past moment");
      step = std::min(step, o->next_step());
      until = std::min(until, o->next_time());
    }
    simulation.run(step - simulation.step_count(), until);
    for (StepObserver* o : observers)
      if ((o->due(simulation) || o->looks_at_every_stop()) && o->observe(simulation)) return true;
  }
  return false;
}

IntervalObserver::IntervalObserver(double interval, double start)
    : interval_(interval), next_(interval > 0.0 ? start + interval : std::numeric_limits<double>::infinity()) {
  if (!(interval >= 0.0)) throw std::invalid_argument("observer: the interval must be >= 0");
}

bool IntervalObserver::observe(const Simulation& simulation) {
  while (next_ <= simulation.time()) next_ += interval_;
  return look(simulation);
}

SnapshotObserver::SnapshotObserver(Callback callback, double interval, double start)
    : IntervalObserver(interval, start), callback_(std::move(callback)) {}

void SnapshotObserver::take(const Simulation& simulation) {
  if (!callback_ || last_ == simulation.step_count()) return;
  callback_(simulation);
  last_ = simulation.step_count();
  ++taken_;
}

bool SnapshotObserver::look(const Simulation& simulation) {
  take(simulation);
  return false;
}

SettleObserver::SettleObserver(SettleMonitor& monitor, double interval, double start)
    : IntervalObserver(interval, start), monitor_(monitor) {}

bool SettleObserver::look(const Simulation& simulation) { return monitor_.update(simulation); }

ImpactProgress progress_of(const Simulation& sim, double time_limit, double elapsed) {
  ImpactProgress progress;
  progress.time = sim.time();
  progress.time_limit = time_limit;
  progress.steps = sim.step_count();
  progress.steps_per_second = static_cast<double>(sim.step_count()) / elapsed;
  progress.particle_steps_per_second = progress.steps_per_second * static_cast<double>(sim.particles().size());
  sim.contacts().for_each([&](const ContactState& contact) {
    if (contact.with_wall)
      ++progress.wall_contacts;
    else
      ++progress.contacts;
  });
  progress.fragments = find_fragments(sim).fragments.size();
  progress.kinetic_energy = sim.energy().kinetic();
  return progress;
}

ProgressObserver::ProgressObserver(Callback callback, double seconds, double time_limit, std::int64_t interval,
                                   std::int64_t start)
    : callback_(std::move(callback)),
      seconds_(seconds),
      time_limit_(time_limit),
      interval_(interval),
      last_step_(start),
      start_(Clock::now()),
      last_(start_) {
  if (interval < 1) throw std::invalid_argument("progress: the interval must be >= 1 step");
}

bool ProgressObserver::observe(const Simulation& simulation) {
  last_step_ = simulation.step_count();
  if (!callback_ || std::chrono::duration<double>(Clock::now() - last_).count() < seconds_) return false;
  last_ = Clock::now();
  callback_(progress_of(simulation, time_limit_, std::chrono::duration<double>(last_ - start_).count()));
  ++reports_;
  return false;
}

}  // namespace aerobreak
