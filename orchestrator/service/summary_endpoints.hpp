#pragma once
#include <cstdint>
#include <string>

#include "orchestrator/service/endpoints.hpp"

namespace aerobreak {

// A study's outcome table as GET /api/studies/ID/outcomes serves it (Endpoints::outcome_tables
// keeps it serialised per study version).
std::string outcome_table_document(Store& store, std::int64_t study);

// Served from the summaries the store keeps (store_summaries.hpp): a study's progress is one row,
// its outcome table one row per grid point, whatever the number of its cases. The outcome table is
// kept serialised per study, keyed by the study's versions (Store::study_versions), with an ETag:
// a request whose If-None-Match names the current one gets 304 and no body.
namespace endpoint {

// GET /api/studies/ID/progress
void get_study_progress(Endpoints&, const httplib::Request&, httplib::Response&);
// GET /api/studies/ID/outcomes
void get_study_outcomes(Endpoints&, const httplib::Request&, httplib::Response&);

}  // namespace endpoint
}  // namespace aerobreak
