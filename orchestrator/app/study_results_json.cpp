#include "orchestrator/app/study_results_json.hpp"

#include "orchestrator/fitting/estimate_json.hpp"

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

nlohmann::ordered_json grid_point_outcomes_json(const GridPointStatistics& statistics) {
  const GridPointOutcomes& cell = statistics.outcomes;
  const std::size_t finished = cell.finished();
  nlohmann::ordered_json outcomes = nlohmann::ordered_json::object();
  for (const auto& [outcome, count] : cell.outcomes)
    outcomes[outcome] = proportion_json(count, wilson_interval(count, cell.trials_for(outcome)));
  return {{"grid_point", cell.grid_point},
          {"cases", cell.cases},
          {"finished", finished},
          {"failed", cell.failed},
          {"outcomes", outcomes},
          {"retained_mass_fraction", mean_json(mean_estimate(statistics.retained_mass_fraction))},
          {"damage_ratio", mean_json(mean_estimate(statistics.damage_ratio))},
          {"energy_per_contact", mean_json(mean_estimate(statistics.energy_per_contact))},
          {"fractured_on_wall", cell.fractured_on_wall},
          {"small_strain_exceeded", cell.small_strain_exceeded},
          {"small_strain_unchecked", cell.small_strain_unchecked}};
}

nlohmann::ordered_json outcome_table_json(const std::vector<GridPointStatistics>& cells) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (const auto& cell : cells) rows.push_back(grid_point_outcomes_json(cell));
  return {{"confidence", 0.95}, {"interval", "wilson"}, {"grid_points", rows}};
}

}  // namespace aerobreak
