#include "orchestrator/service/routes.hpp"

#include <stdexcept>

#include "orchestrator/service/correlation_endpoints.hpp"
#include "orchestrator/service/dashboard_endpoints.hpp"
#include "orchestrator/service/http_api.hpp"
#include "orchestrator/service/http_support.hpp"
#include "orchestrator/service/search_endpoints.hpp"
#include "orchestrator/service/summary_endpoints.hpp"
#include "orchestrator/service/table_endpoints.hpp"
#include "orchestrator/service/web_endpoints.hpp"

namespace aerobreak {
namespace {

using namespace endpoint;

// Adding an endpoint: one line here, its operation in schemas/openapi.json (the tests hold the two
// together).
const Route kRoutes[] = {
    {"GET", "/api/health", "getHealth", get_health},
    {"GET", "/api/openapi.json", "getOpenApi", get_openapi},
    {"GET", "/api/templates", "getTemplates", get_templates},
    {"GET", "/api/case-fields", "getCaseFields", get_case_fields},
    {"GET", "/api/studies", "listStudies", list_studies},
    {"POST", "/api/studies", "submitStudy", submit_study},
    {"GET", "/api/studies/{id}", "getStudy", get_study},
    {"GET", "/api/studies/{id}/progress", "getStudyProgress", get_study_progress},
    {"GET", "/api/studies/{id}/cases", "listStudyCases", list_study_cases},
    {"GET", "/api/studies/{id}/results", "listStudyResults", list_study_results},
    {"GET", "/api/studies/{id}/outcomes", "getStudyOutcomes", get_study_outcomes},
    {"GET", "/api/studies/{id}/tables", "getStudyTable", get_study_table},
    {"GET", "/api/studies/{id}/search", "getStudySearch", get_study_search},
    {"GET", "/api/studies/{id}/correlations", "getStudyCorrelations", get_study_correlations},
    {"GET", "/api/studies/{id}/correlations/{name}", "getStudyCorrelation", get_study_correlation},
    {"POST", "/api/studies/{id}/cancel", "cancelStudy", cancel_study},
    {"GET", "/api/cases/{id}", "getCase", get_case},
    {"GET", "/api/jobs", "listJobs", list_jobs},
    {"GET", "/api/progress", "listStudyProgress", list_study_progress},
    {"GET", "/api/studies/{id}/grid", "getStudyGrid", get_study_grid},
    {"GET", "/api/studies/{id}/case-table", "getStudyCaseTable", get_study_case_table},
    {"GET", "/api/studies/{id}/fragment-sizes", "getStudyFragmentSizes", get_study_fragment_sizes},
    {"GET", "/api/cases/{id}/data", "getCaseData", get_case_data},
    {"GET", "/", "getDashboard", get_dashboard_file, kDashboardFiles},
};

// What each path parameter matches: a decimal id, or a fit's name (a path segment, bounded).
std::string parameter_pattern(std::string_view name) {
  if (name == "id") return R"((\d+))";
  if (name == "name") return R"(([^/]{1,200}))";
  throw std::logic_error("routes: no pattern for the path parameter {" + std::string(name) + "}");
}

}  // namespace

std::span<const Route> routes() { return kRoutes; }

std::string route_pattern(const Route& route) {
  if (route.pattern) return route.pattern;
  std::string pattern;
  for (std::size_t at = 0; at < route.path.size();) {
    const std::size_t open = route.path.find('{', at);
    if (open == std::string_view::npos) {
      pattern += route.path.substr(at);
      break;
    }
    const std::size_t close = route.path.find('}', open);
    pattern += route.path.substr(at, open - at);
    pattern += parameter_pattern(route.path.substr(open + 1, close - open - 1));
    at = close + 1;
  }
  return pattern;
}

void register_routes(httplib::Server& server, Endpoints& endpoints) {
  for (const Route& route : routes()) {
    auto handler =
        guarded([&endpoints, answer = route.handler](const httplib::Request& request, httplib::Response& response) {
          answer(endpoints, request, response);
        });
    if (route.method == "POST")
      server.Post(route_pattern(route), std::move(handler));
    else
      server.Get(route_pattern(route), std::move(handler));
  }
}

}  // namespace aerobreak
