#pragma once
#include "orchestrator/service/service.hpp"

namespace aerobreak {

// Registers every endpoint of schemas/openapi.json, the bearer-token check for mutating requests
// and the JSON error bodies (every 4xx names what was wrong) on `server`.
void register_http_api(httplib::Server& server, Store& store, Scheduler* scheduler, const ServiceOptions& options);

}  // namespace aerobreak
