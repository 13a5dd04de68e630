#pragma once
#include <chrono>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

namespace aerobreak {

class Simulation;
class SettleMonitor;

// Something that looks at a running simulation at steps of its own choosing (run_observed).
class StepObserver {
 public:
  virtual ~StepObserver() = default;
  // The step count at which it next wants to look; must lie ahead of the simulation's.
  virtual std::int64_t next_step() const = 0;
  // Looks at the simulation at that step; true stops the run.
  virtual bool observe(const Simulation& simulation) = 0;
  // Whether it also looks whenever the run stops for another observer.
  virtual bool looks_at_every_stop() const { return false; }
};

// Steps `simulation` until `limit_steps` or until an observer stops it. Each observer sees the
// simulation at every step it asks for, in the order of `observers` where several ask for the
// same step (one that looks at every stop looks then too); one that stops the run is the last to
// look. The stepping is Simulation::run in
// stretches between those steps, which gives the trajectory of one uninterrupted run to the last
// bit. Returns whether an observer stopped the run.
bool run_observed(Simulation& simulation, std::int64_t limit_steps, const std::vector<StepObserver*>& observers);

// An observer that looks every `interval` steps after the step it was made at (never for an
// interval of 0).
class IntervalObserver : public StepObserver {
 public:
  std::int64_t next_step() const final { return next_; }
  bool observe(const Simulation& simulation) final;

 protected:
  IntervalObserver(std::int64_t interval, std::int64_t start);
  ~IntervalObserver() override = default;
  virtual bool look(const Simulation& simulation) = 0;

 private:
  std::int64_t interval_;
  std::int64_t next_;
};

// Snapshots: at every interval, and whenever take() is called (the start and the end of a run),
// never twice at one step.
class SnapshotObserver final : public IntervalObserver {
 public:
  using Callback = std::function<void(const Simulation&)>;
  SnapshotObserver(Callback callback, std::int64_t interval, std::int64_t start = 0);
  void take(const Simulation& simulation);
  std::size_t taken() const { return taken_; }

 private:
  bool look(const Simulation& simulation) override;
  Callback callback_;
  std::int64_t last_ = -1;
  std::size_t taken_ = 0;
};

// The settle check (SettleMonitor, both of its rules): stops the run once the outcome is settled.
class SettleObserver final : public IntervalObserver {
 public:
  SettleObserver(SettleMonitor& monitor, std::int64_t interval, std::int64_t start = 0);

 private:
  bool look(const Simulation& simulation) override;
  SettleMonitor& monitor_;
};

// Where a running impact stands (for progress output).
struct ImpactProgress {
  double time = 0.0;
  double time_limit = 0.0;
  std::int64_t steps = 0;
  double steps_per_second = 0.0;
  double particle_steps_per_second = 0.0;
  std::size_t contacts = 0;       // particle-particle
  std::size_t wall_contacts = 0;
  std::size_t fragments = 0;
  double kinetic_energy = 0.0;
};
ImpactProgress progress_of(const Simulation& simulation, double time_limit, double elapsed_seconds);

// Progress: looks whenever the run stops and at least every `interval` steps, and reports when
// `seconds` of wall-clock time have passed since it last reported (or since it was made).
class ProgressObserver final : public StepObserver {
 public:
  using Callback = std::function<void(const ImpactProgress&)>;
  ProgressObserver(Callback callback, double seconds, double time_limit, std::int64_t interval,
                   std::int64_t start = 0);
  std::int64_t next_step() const override { return last_step_ + interval_; }
  bool observe(const Simulation& simulation) override;
  bool looks_at_every_stop() const override { return true; }
  std::size_t reports() const { return reports_; }

 private:
  using Clock = std::chrono::steady_clock;
  Callback callback_;
  double seconds_;
  double time_limit_;
  std::int64_t interval_;
  std::int64_t last_step_;
  Clock::time_point start_;
  Clock::time_point last_;
  std::size_t reports_ = 0;
};

}  // namespace aerobreak
