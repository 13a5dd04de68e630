#include "orchestrator/search/search_json.hpp"

namespace aerobreak {
namespace {

nlohmann::ordered_json number_or_null(const std::optional<double>& value) {
  return value ? nlohmann::ordered_json(*value) : nlohmann::ordered_json(nullptr);
}

}  // namespace

nlohmann::ordered_json to_json(const CrossingEstimate& e) {
  return {{"response", e.response},
          {"level", e.level},
          {"estimate", number_or_null(e.estimate)},
          {"lower", number_or_null(e.lower)},
          {"upper", number_or_null(e.upper)},
          {"fit", e.fit},
          {"status", e.status},
          {"narrow_enough", e.narrow_enough},
          {"found", e.found}};
}

nlohmann::ordered_json to_json(const std::vector<CrossingEstimate>& estimates) {
  auto out = nlohmann::ordered_json::array();
  for (const auto& e : estimates) out.push_back(to_json(e));
  return out;
}

nlohmann::ordered_json round_json(int round, const RoundPlan& plan) {
  return {{"round", round},
          {"results", plan.results},
          {"estimates", to_json(plan.estimates)},
          {"values", plan.values},
          {"reasons", plan.reasons}};
}

}  // namespace aerobreak
