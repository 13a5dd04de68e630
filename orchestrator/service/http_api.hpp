#pragma once
#include "orchestrator/service/endpoints.hpp"

namespace aerobreak {

// Registers every route of routes.hpp, the checks every request passes first (bounds, origin,
// bearer token for mutating requests) and the JSON error bodies (every 4xx names what was wrong)
// on `server`.
void register_http_api(httplib::Server& server, Endpoints& endpoints);

// The service's own endpoints: its health and API description, the studies to start from, the case
// fields' labels and units, the studies, their cases and results, and the worker jobs
// (schemas/openapi.json documents each).
namespace endpoint {
void get_health(Endpoints&, const httplib::Request&, httplib::Response&);
void get_openapi(Endpoints&, const httplib::Request&, httplib::Response&);
void get_templates(Endpoints&, const httplib::Request&, httplib::Response&);
void get_case_fields(Endpoints&, const httplib::Request&, httplib::Response&);
void list_studies(Endpoints&, const httplib::Request&, httplib::Response&);
void submit_study(Endpoints&, const httplib::Request&, httplib::Response&);
void get_study(Endpoints&, const httplib::Request&, httplib::Response&);
void list_study_cases(Endpoints&, const httplib::Request&, httplib::Response&);
void list_study_results(Endpoints&, const httplib::Request&, httplib::Response&);
void cancel_study(Endpoints&, const httplib::Request&, httplib::Response&);
void get_case(Endpoints&, const httplib::Request&, httplib::Response&);
void list_jobs(Endpoints&, const httplib::Request&, httplib::Response&);
}  // namespace endpoint

}  // namespace aerobreak
