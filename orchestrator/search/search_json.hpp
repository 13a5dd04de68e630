#pragma once
#include <nlohmann/json.hpp>
#include <vector>

#include "orchestrator/search/boundary_search.hpp"

namespace aerobreak {

// {"response", "level", "estimate", "lower", "upper", "fit", "status", "narrow_enough", "found"};
// absent numbers are null.
nlohmann::ordered_json to_json(const CrossingEstimate& estimate);
nlohmann::ordered_json to_json(const std::vector<CrossingEstimate>& estimates);

// A round's record: its number, the results and estimates it was decided from, its values and why.
nlohmann::ordered_json round_json(int round, const RoundPlan& plan);

}  // namespace aerobreak
