#pragma once
#include <nlohmann/json.hpp>
#include <vector>

#include "orchestrator/service/endpoints.hpp"

namespace aerobreak {

// Each group of a search: its axis values, state, rounds, cases and current crossings with their
// 95 % intervals; with every round's record when the groups carry their history.
nlohmann::ordered_json search_groups_json(const std::vector<SearchGroupRecord>& groups);

namespace endpoint {
// GET /api/studies/ID/search: the study's adaptive search (docs/ADAPTIVE.md), every round of
// every group (404 for a study without a search).
void get_study_search(Endpoints&, const httplib::Request&, httplib::Response&);
}  // namespace endpoint

}  // namespace aerobreak
