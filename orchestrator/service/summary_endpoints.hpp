#pragma once
#include <httplib.h>

#include "orchestrator/store/store.hpp"

namespace aerobreak {

// GET /api/studies/ID/progress and GET /api/studies/ID/outcomes, served from the summaries the
// store keeps (store_summaries.hpp): a study's progress is one row, its outcome table one row per
// grid point, whatever the number of its cases. The outcome table is kept serialised per study,
// keyed by the study's versions (Store::study_versions), with an ETag: a request whose
// If-None-Match names the current one gets 304 and no body.
void register_summary_endpoints(httplib::Server& server, Store& store);

}  // namespace aerobreak
