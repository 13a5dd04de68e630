#include "orchestrator/service/summary_endpoints.hpp"

#include <map>
#include <memory>
#include <mutex>
#include <random>
#include <string>

#include "orchestrator/service/api_json.hpp"
#include "orchestrator/service/http_support.hpp"

namespace aerobreak {
namespace {

// A serialised outcome table and the versions of the study it was made from.
struct OutcomeTable {
  StudyVersions versions;
  std::string etag;
  std::string body;
};

// The latest outcome table of each study asked for, at most kMaxStudies of them. ETags carry a
// token drawn when the service starts, so that a tag from another process (another store on the
// same port) never matches.
class OutcomeTableCache {
 public:
  OutcomeTableCache() : instance_(std::to_string(std::random_device{}())) {}

  std::shared_ptr<const OutcomeTable> find(std::int64_t study, const StudyVersions& versions) const {
    std::lock_guard lock(mutex_);
    const auto found = tables_.find(study);
    if (found == tables_.end() || found->second->versions.case_states != versions.case_states ||
        found->second->versions.result_set != versions.result_set)
      return nullptr;
    return found->second;
  }

  std::shared_ptr<const OutcomeTable> make(Store& store, std::int64_t study, const StudyVersions& versions) {
    // The versions were read before the table: a table may be newer than its tag, never older, so
    // that a client holding the tag is never told an out-of-date table is current.
    auto json = outcome_table_json(store.outcomes(study));
    json["study"] = study;
    auto table = std::make_shared<const OutcomeTable>(OutcomeTable{
        versions,
        "\"" + instance_ + "-" + std::to_string(study) + "-" + std::to_string(versions.case_states) + "-" +
            std::to_string(versions.result_set) + "\"",
        json.dump()});
    std::lock_guard lock(mutex_);
    if (tables_.size() >= kMaxStudies) tables_.clear();
    tables_[study] = table;
    return table;
  }

 private:
  static constexpr std::size_t kMaxStudies = 64;
  const std::string instance_;
  mutable std::mutex mutex_;
  std::map<std::int64_t, std::shared_ptr<const OutcomeTable>> tables_;
};

}  // namespace

void register_summary_endpoints(httplib::Server& server, Store& store) {
  server.Get(R"(/api/studies/(\d+)/progress)",
             guarded([&store](const httplib::Request& request, httplib::Response& response) {
               const auto id = path_id(request);
               const auto progress = store.progress(id);
               if (!progress) throw RequestError{404, "no study " + std::to_string(id)};
               send_json(response, 200, to_json(*progress));
             }));
  auto cache = std::make_shared<OutcomeTableCache>();
  server.Get(R"(/api/studies/(\d+)/outcomes)",
             guarded([&store, cache](const httplib::Request& request, httplib::Response& response) {
               const auto id = path_id(request);
               const auto versions = store.study_versions(id);
               if (!versions) throw RequestError{404, "no study " + std::to_string(id)};
               auto table = cache->find(id, *versions);
               if (!table) table = cache->make(store, id, *versions);
               response.set_header("ETag", table->etag);
               response.set_header("Cache-Control", "no-cache");
               if (names_current_tag(request, table->etag)) {
                 response.status = 304;
                 return;
               }
               response.status = 200;
               response.set_content(table->body, "application/json");
             }));
}

}  // namespace aerobreak
