#pragma once
#include <nlohmann/json.hpp>
#include <vector>

#include "orchestrator/store/store_types.hpp"

namespace aerobreak {

// A study's results in the REST API's forms (schemas/openapi.json), which `aerobreak run` prints as
// tables too (orchestrator/cli/outcome_table.hpp, search_table.hpp) as `aerobreak study results`
// does from the API.

// One grid point: its axis values, cases, finished and failed counts, per outcome the count and
// the probability with the 95 % Wilson interval (fitting/proportion.hpp), of stick, bounce and
// break-up among the determined results, of undetermined among all (GridPointOutcomes::trials_for),
// the means of the retained mass fraction and the damage ratio over the determined results and of
// the energy per contact over all, with their Student intervals (fitting/mean_estimate.hpp), and the flags.
nlohmann::ordered_json grid_point_outcomes_json(const GridPointStatistics& statistics);
// Each grid point's row as above.
nlohmann::ordered_json outcome_table_json(const std::vector<GridPointStatistics>& cells);

// Each group of a search: its axis values, state, rounds, cases and current crossings with their
// 95 % intervals; with every round's record when the groups carry their history.
nlohmann::ordered_json search_groups_json(const std::vector<SearchGroupRecord>& groups);

}  // namespace aerobreak
