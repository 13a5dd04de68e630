#pragma once
#include "orchestrator/service/endpoints.hpp"

namespace aerobreak {
namespace endpoint {
// GET /api/studies/ID/search: the study's adaptive search (docs/ADAPTIVE.md), every round of
// every group (404 for a study without a search).
void get_study_search(Endpoints&, const httplib::Request&, httplib::Response&);
}  // namespace endpoint

}  // namespace aerobreak
