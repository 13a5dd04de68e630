#pragma once
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace aerobreak {

// The outcome classes of an impact (docs/IMPACT.md): stick = nothing leaves the wall; bounce = the
// cluster leaves it intact; break-up = mass leaves it in pieces; undetermined = the time limit came
// first (never counted as any of the three).
enum class Outcome { stick, bounce, break_up, undetermined };
inline constexpr Outcome kDeterminedOutcomes[] = {Outcome::stick, Outcome::bounce, Outcome::break_up};
std::string_view to_string(Outcome outcome);
std::optional<Outcome> parse_outcome(std::string_view text);

// One finished case as the statistics see it: what the store's results row and fragments say.
struct CaseOutcome {
  std::size_t grid_point = 0;  // index into CaseOutcomeTable::grid_points
  Outcome outcome = Outcome::undetermined;
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
