#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "engine/cluster/cluster.hpp"
#include "engine/core/particles.hpp"
#include "engine/core/run_clock.hpp"
#include "engine/impact/impact_case.hpp"
#include "engine/impact/impact_result.hpp"
#include "engine/impact/run_observers.hpp"

namespace aerobreak {

class Simulation;
class SettleMonitor;

struct ImpactRunOptions {
  // Called with the simulation at the start, every snapshot interval of the case, and at the end.
  std::function<void(const Simulation&)> snapshot;
  // Called about every `progress_seconds` of wall-clock time while the impact runs.
  std::function<void(const ImpactProgress&)> progress;
  double progress_seconds = 2.0;
  // One-line notes on the set-up stages (cluster built, relaxed, ...).
  std::function<void(const std::string&)> log;
};

// The cluster of a case as it enters the impact: generated or read, then relaxed (unless the case
// says not to or the normal law has no adhesion). Returns the particles (at rest, centred where the
// source put them) and fills `relaxation`.
Particles prepare_cluster(const ImpactCase& impact_case, RelaxationSummary& relaxation,
                          const std::function<void(const std::string&)>& log = {});

// An impact set up and not yet run: the simulation before its first step, and the result with
// its set-up filled in (the case, the cluster before, the time step, the initial contacts, the
// contact energies and dimensionless groups, the settle window).
struct PreparedImpact {
  ImpactResult result;
  std::unique_ptr<Simulation> simulation;
  ContactEvents pair_start;  // the engine counts the bonds of the start as made: events count from here
  ContactEvents wall_start;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> initial_contacts;  // (i < j), sorted
  PreparedImpact();
  PreparedImpact(PreparedImpact&&) noexcept;
  ~PreparedImpact();
};

// Prepares the cluster, turns it to the seeded random orientation, places it `gap` above the wall
// with every primary at the impact velocity and builds the simulation (docs/IMPACT.md section 3).
PreparedImpact prepare_impact(const ImpactCase& impact_case, const ImpactRunOptions& options = {});

// How often a running impact is looked at: the settle check 20 times per quiet window and
// snapshots at the case's interval (0: none), in simulated time, the same whatever the steps;
// progress about every 10^6 particle-steps. The run ends at the case's time limit.
struct ImpactSchedule {
  double check_interval = 0.0;
  double snapshot_interval = 0.0;
  std::int64_t progress_steps = 0;
};
ImpactSchedule impact_schedule(const ImpactResult& prepared, std::size_t particles);

// Runs a prepared impact until the settle check (SettleMonitor, both rules) finds its outcome
// settled or the time limit comes, with snapshots and progress on the way (run_observed); returns
// the wall-clock and CPU seconds of stepping. The result is then measured by measure_impact
// (impact_measurement.hpp).
ElapsedTimes run_prepared_impact(PreparedImpact& prepared, SettleMonitor& monitor,
                                 const ImpactRunOptions& options = {});

// Runs one impact case end to end (docs/IMPACT.md): prepares the cluster, turns it to the seeded
// random orientation, places it `gap` above the wall with every primary at the impact velocity,
// runs until the settle criterion holds or the time limit comes, and analyses the final state.
// Throws std::invalid_argument / std::runtime_error for cases the engine cannot run.
ImpactResult run_impact(const ImpactCase& impact_case, const ImpactRunOptions& options = {});

// The orientation and velocity a case prescribes, for a wall with normal +z.
Rotation impact_orientation(const ImpactCase& impact_case);
Vec3 impact_velocity(const ImpactCase& impact_case);

}  // namespace aerobreak
