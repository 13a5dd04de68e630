#pragma once
// The measurement of an impact (docs/IMPACT.md): what a result says about the cluster before the
// impact and about the state a run ends in.
#include <cstdint>
#include <utility>
#include <vector>

#include "engine/core/particles.hpp"
#include "engine/impact/impact_result.hpp"
#include "engine/impact/impact_run.hpp"

namespace aerobreak {

class Simulation;
class SettleMonitor;

// The particle-particle contacts of a simulation as sorted pairs (i < j).
std::vector<std::pair<std::uint32_t, std::uint32_t>> contact_pairs(const Simulation& sim);

// The shape of the primaries `members` of `p` holding `contacts` contacts among themselves:
// radius of gyration, fractal dimension, coordination number, filling factor.
ClusterShape shape_of(const Particles& p, const std::vector<std::uint32_t>& members, std::size_t contacts);

// Fills in the result of a finished run: the run's counters as the simulation left them
// (`stepping`: the wall-clock and CPU seconds of stepping), then the final state (settled: the
// state the monitor judged, which is the final one, the run having stopped right after the
// judgement): fragments, outcome, restitution, compaction of the largest fragment, damage and the
// small-strain check.
void measure_impact(PreparedImpact& prepared, const SettleMonitor& monitor, const ElapsedTimes& stepping);

}  // namespace aerobreak
