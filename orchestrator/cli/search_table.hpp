#pragma once
#include <nlohmann/json.hpp>
#include <string>

namespace aerobreak {

// The groups of an adaptive search (the "groups" of GET /api/studies/ID/search) as text: one line
// per group with its state, rounds and cases, then one per crossing with its estimate and 95 %
// interval, in the unit of the searched axis (`unit`: m/s, d/tau, ...; empty for a ratio or count).
std::string format_search_table(const nlohmann::ordered_json& groups, const std::string& axis, const std::string& unit);

}  // namespace aerobreak
