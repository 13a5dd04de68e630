#include "orchestrator/service/search_endpoints.hpp"

#include <string>

#include "orchestrator/app/study_results_json.hpp"
#include "orchestrator/service/http_support.hpp"

namespace aerobreak {
namespace endpoint {

void get_study_search(Endpoints& e, const httplib::Request& request, httplib::Response& response) {
  const auto id = path_id(request);
  const auto study = e.store.study(id);
  if (!study) throw RequestError{404, "no study " + std::to_string(id)};
  if (!study->document.contains("search"))
    throw RequestError{404, "study " + std::to_string(id) + " has no adaptive search"};
  const auto progress = e.store.progress(id);
  send_json(response, 200,
            {{"study", id},
             {"search", study->document["search"]},
             {"complete", progress && progress->complete},
             {"groups", search_groups_json(e.store.search_groups(id, true))}});
}

}  // namespace endpoint

}  // namespace aerobreak
