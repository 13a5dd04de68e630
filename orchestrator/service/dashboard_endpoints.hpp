#pragma once
#include <httplib.h>

#include "orchestrator/service/service.hpp"

namespace aerobreak {

// What the dashboard (web/) asks the server to aggregate, so that a study of 100,000 cases is never
// pulled into the browser: progress of the newest studies, per-grid-point statistics with the
// study's axes, a filtered and paged case table, fragment-size counts, and a case's HDF5 file
// (schemas/openapi.json documents each).
void register_dashboard_endpoints(httplib::Server& server, Store& store, const ServiceOptions& options);

}  // namespace aerobreak
