#include "orchestrator/service/summary_endpoints.hpp"

#include <string>

#include "orchestrator/app/study_results_json.hpp"
#include "orchestrator/service/api_json.hpp"
#include "orchestrator/service/http_support.hpp"

namespace aerobreak {

std::string outcome_table_document(Store& store, std::int64_t study) {
  auto json = outcome_table_json(store.grid_statistics(study));
  json["study"] = study;
  return json.dump();
}

namespace endpoint {

void get_study_progress(Endpoints& e, const httplib::Request& request, httplib::Response& response) {
  const auto id = path_id(request);
  const auto progress = e.store.progress(id);
  if (!progress) throw RequestError{404, "no study " + std::to_string(id)};
  auto json = to_json(*progress);
  if (progress->search_groups > 0) json["search"] = search_groups_json(e.store.search_groups(id, false));
  send_json(response, 200, json);
}

void get_study_outcomes(Endpoints& e, const httplib::Request& request, httplib::Response& response) {
  e.outcome_tables.serve(e.store, path_id(request), request, response);
}

}  // namespace endpoint
}  // namespace aerobreak
