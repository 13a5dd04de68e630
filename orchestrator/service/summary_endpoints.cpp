#include "orchestrator/service/summary_endpoints.hpp"

#include <memory>
#include <string>

#include "orchestrator/service/api_json.hpp"
#include "orchestrator/service/http_support.hpp"
#include "orchestrator/service/search_endpoints.hpp"
#include "orchestrator/service/versioned_documents.hpp"

namespace aerobreak {

void register_summary_endpoints(httplib::Server& server, Store& store) {
  server.Get(R"(/api/studies/(\d+)/progress)",
             guarded([&store](const httplib::Request& request, httplib::Response& response) {
               const auto id = path_id(request);
               const auto progress = store.progress(id);
               if (!progress) throw RequestError{404, "no study " + std::to_string(id)};
               auto json = to_json(*progress);
               if (progress->search_groups > 0) json["search"] = search_groups_json(store.search_groups(id, false));
               send_json(response, 200, json);
             }));
  const auto tables = std::make_shared<VersionedDocuments>([&store](std::int64_t study) {
    auto json = outcome_table_json(store.outcomes(study));
    json["study"] = study;
    return json.dump();
  });
  server.Get(R"(/api/studies/(\d+)/outcomes)",
             guarded([&store, tables](const httplib::Request& request, httplib::Response& response) {
               tables->serve(store, path_id(request), request, response);
             }));
}

}  // namespace aerobreak
