#include "orchestrator/service/search_endpoints.hpp"

#include <string>

#include "orchestrator/service/http_support.hpp"

namespace aerobreak {
namespace {

using Json = nlohmann::ordered_json;

Json round_json(const SearchRoundRecord& round) {
  Json out{{"round", round.round}, {"decided_at", round.decided_at}};
  for (const auto& [key, value] : round.plan.items())
    if (key != "round") out[key] = value;
  return out;
}

}  // namespace

Json search_groups_json(const std::vector<SearchGroupRecord>& groups) {
  Json out = Json::array();
  for (const auto& g : groups) {
    Json group{{"position", g.position},
               {"group", g.group_point},
               {"state", g.state},
               {"rounds", g.rounds},
               {"cases", g.cases},
               {"estimates", g.estimates},
               {"note", g.note ? Json(*g.note) : Json(nullptr)},
               {"updated_at", g.updated_at}};
    if (!g.history.empty()) {
      group["history"] = Json::array();
      for (const auto& round : g.history) group["history"].push_back(round_json(round));
    }
    out.push_back(std::move(group));
  }
  return out;
}

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
