#pragma once
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

// The outcome classes (ImpactOutcome), their names and their order: the engine's outcome rule.
#include "engine/impact/outcome.hpp"

namespace aerobreak {

// One finished case as the statistics see it: what the store's results row and fragments say.
struct CaseOutcome {
  std::size_t grid_point = 0;  // index into CaseOutcomeTable::grid_points
  ImpactOutcome outcome = ImpactOutcome::undetermined;
  std::optional<double> retained_mass_fraction;  // mass in fragments that stay on the wall / total
  std::optional<double> restitution;             // normal restitution of the largest fragment
  std::optional<double> damage_ratio;            // contacts broken / initial contacts
  std::optional<double> energy_per_contact;      // E_kin / (N_c E_break)
  bool small_strain_exceeded = false;            // left JKR's small-strain range
  std::vector<std::int64_t> reentrained_sizes;   // primaries of each fragment that left the wall
  std::int64_t primaries = 0;                    // N of the cluster (0: not known)
};

// A study's finished cases and its grid: the input of every fit (compute_correlations).
struct CaseOutcomeTable {
  std::vector<std::string> axes;                    // the study's axis names, in its order
  std::vector<nlohmann::ordered_json> grid_points;  // per grid point: axis name -> value
  std::vector<CaseOutcome> cases;
};

}  // namespace aerobreak
