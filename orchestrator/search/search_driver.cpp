#include "orchestrator/search/search_driver.hpp"

#include "orchestrator/search/boundary_search.hpp"
#include "orchestrator/search/search_json.hpp"

namespace aerobreak {
namespace {

std::vector<SearchObservation> observations_of(const SearchGroupWork& work, const std::string& axis) {
  std::vector<SearchObservation> out;
  for (const auto& c : work.finished)
    if (!c.outcome.empty() && c.grid_point.contains(axis) && c.grid_point[axis].is_number())
      out.push_back({c.grid_point[axis].get<double>(), c.outcome, c.round});
  return out;
}

}  // namespace

SearchDriver::SearchDriver(Store& store, std::function<void(const std::string&)> log)
    : store_(store), log_(std::move(log)) {}

const Study& SearchDriver::study(std::int64_t study_id, const nlohmann::ordered_json& document) {
  auto found = studies_.find(study_id);
  if (found == studies_.end()) found = studies_.emplace(study_id, parse_study(document)).first;
  return found->second;
}

SearchDecision SearchDriver::decide(const SearchGroupWork& work) {
  SearchDecision decision;
  decision.study_id = work.study_id;
  decision.position = work.position;
  decision.round = work.rounds;
  try {
    const Study& s = study(work.study_id, work.study_document);
    const RoundPlan plan = plan_round(*s.search, observations_of(work, s.search->axis),
                                      round_context(s.seed, work.position, work.rounds, work.cases));
    decision.state = std::string(to_string(plan.state));
    decision.estimates = to_json(plan.estimates);
    decision.plan = round_json(work.rounds, plan);
    for (std::size_t k = 0; k < plan.values.size(); ++k) {
      const StudyCase c = search_case(s, work.group_point, plan.values[k], work.cases + static_cast<int>(k));
      decision.cases.push_back({c.hash, c.document, c.grid_point, c.grid_key, c.replicate, work.position, work.rounds});
    }
  } catch (const std::exception& error) {
    decision.state = "error";
    decision.cases.clear();
    decision.note = error.what();
  }
  return decision;
}

std::size_t SearchDriver::advance() {
  std::size_t placed = 0;
  for (const auto& work : store_.search_work()) {
    const SearchDecision decision = decide(work);
    if (!store_.record_search_decision(decision)) continue;
    placed += decision.cases.size();
    if (log_ && decision.cases.empty())
      log_("search of study " + std::to_string(work.study_id) + " group " + std::to_string(work.position) + " " +
           decision.state + " after " + std::to_string(work.rounds) + " round(s), " + std::to_string(work.cases) +
           " cases" + (decision.note.empty() ? "" : ": " + decision.note));
  }
  return placed;
}

}  // namespace aerobreak
