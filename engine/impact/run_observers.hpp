#pragma once
#include <chrono>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

namespace aerobreak {

class Simulation;
class SettleMonitor;

// Something that looks at a running simulation at moments of its own choosing (run_observed): at a
// step count, or at the first step that brings the simulated time to a moment or past it (the
// step changes during a run: docs/MODEL.md 9.2).
class StepObserver {
 public:
  virtual ~StepObserver() = default;
  // The step count at which it next wants to look (none: the largest count); ahead of the
  // simulation's.
  virtual std::int64_t next_step() const { return std::numeric_limits<std::int64_t>::max(); }
  // The simulated time from which it next wants to look (none: infinite); ahead of the simulation's.
  virtual double next_time() const { return std::numeric_limits<double>::infinity(); }
  // Looks at the simulation; true stops the run.
  virtual bool observe(const Simulation& simulation) = 0;
  // Whether it also looks whenever the run stops for another observer.
  virtual bool looks_at_every_stop() const { return false; }
  // Whether the simulation has reached the step or the time it asked for.
  bool due(const Simulation& simulation) const;
};

// Steps `simulation` until its time reaches `time_limit` or an observer stops it. Each observer
// sees the simulation at every step and time it asks for (at the first step at or past that
// time), in the order of `observers` where several are due at once (one that looks at every stop
// looks then too); one that stops the run is the last to look. The stepping is Simulation::run in
// stretches between those moments, which gives the trajectory of one uninterrupted run to the last
// bit. Returns whether an observer stopped the run.
bool run_observed(Simulation& simulation, double time_limit, const std::vector<StepObserver*>& observers);

// An observer that looks every `interval` of simulated time after the time it was made at (never
// for an interval of 0): at the first step at or past start + k interval, k = 1, 2, ...; a step
// longer than the interval passes the moments it covers at once.
class IntervalObserver : public StepObserver {
 public:
  double next_time() const final { return next_; }
  bool observe(const Simulation& simulation) final;

 protected:
  IntervalObserver(double interval, double start);
  ~IntervalObserver() override = default;
  virtual bool look(const Simulation& simulation) = 0;

 private:
  double interval_;
  double next_;
};

// Snapshots: at every interval of simulated time, and whenever take() is called (the start and the
// end of a run), never twice at one step.
class SnapshotObserver final : public IntervalObserver {
 public:
  using Callback = std::function<void(const Simulation&)>;
  SnapshotObserver(Callback callback, double interval, double start = 0.0);
  void take(const Simulation& simulation);
  std::size_t taken() const { return taken_; }

 private:
  bool look(const Simulation& simulation) override;
  Callback callback_;
  std::int64_t last_ = -1;
  std::size_t taken_ = 0;
};

// The settle check (SettleMonitor, all of its rules): stops the run once the outcome is settled;
// looks every `interval` of simulated time.
class SettleObserver final : public IntervalObserver {
 public:
  SettleObserver(SettleMonitor& monitor, double interval, double start = 0.0);

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
  std::size_t contacts = 0;  // particle-particle
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
  ProgressObserver(Callback callback, double seconds, double time_limit, std::int64_t interval, std::int64_t start = 0);
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
