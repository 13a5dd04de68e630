#pragma once
#include <httplib.h>

#include <memory>

#include "orchestrator/service/service.hpp"
#include "orchestrator/store/data_file_check.hpp"

namespace aerobreak {

// What the dashboard (web/) asks the server to aggregate, so that a study of 100,000 cases is never
// pulled into the browser: progress of the newest studies, per-grid-point statistics with the
// study's axes, a filtered and paged case table, fragment-size counts, and a case's HDF5 file
// (schemas/openapi.json documents each); `checker` verifies a case file before it is served.
void register_dashboard_endpoints(httplib::Server& server, Store& store, const ServiceOptions& options,
                                  std::shared_ptr<DataFileChecker> checker);

}  // namespace aerobreak
