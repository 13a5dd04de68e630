#include "orchestrator/fitting/case_groups.hpp"

#include <algorithm>
#include <limits>
#include <map>

namespace aerobreak {

std::vector<CaseGroup> group_cases(const CaseOutcomeTable& table, const std::string& speed_axis,
                                   const std::vector<std::string>& pooled_axes, const std::string& prefix) {
  std::vector<CaseGroup> groups;
  std::map<std::string, std::size_t> index;
  std::vector<std::size_t> group_of_point(table.grid_points.size());
  for (std::size_t g = 0; g < table.grid_points.size(); ++g) {
    nlohmann::ordered_json axes = table.grid_points[g];
    axes.erase(speed_axis);
    for (const auto& axis : pooled_axes) axes.erase(axis);
    const auto [it, inserted] = index.emplace(axes.dump(), groups.size());
    if (inserted) groups.push_back({prefix + std::to_string(groups.size() + 1), axes, {}, {}});
    groups[it->second].grid_points.push_back(g);
    group_of_point[g] = it->second;
  }
  for (const CaseOutcome& c : table.cases) groups[group_of_point.at(c.grid_point)].cases.push_back(&c);
  return groups;
}

std::vector<CaseGroup> condition_groups(const CaseOutcomeTable& table, const CorrelationRequest& request) {
  std::vector<std::string> modelled;
  for (const auto& covariate : request.covariates) modelled.push_back(covariate.axis);
  return group_cases(table, request.speed_axis, modelled, "c");
}

std::vector<std::vector<const CaseOutcome*>> cases_by_point(const CaseOutcomeTable& table) {
  std::vector<std::vector<const CaseOutcome*>> by_point(table.grid_points.size());
  for (const CaseOutcome& c : table.cases) by_point.at(c.grid_point).push_back(&c);
  return by_point;
}

double axis_number(const nlohmann::ordered_json& grid_point, const std::string& axis) {
  const auto found = grid_point.find(axis);
  if (found == grid_point.end() || !found->is_number()) return std::numeric_limits<double>::quiet_NaN();
  return found->get<double>();
}

std::vector<const CaseOutcome*> determined_cases(const std::vector<const CaseOutcome*>& cases) {
  std::vector<const CaseOutcome*> determined;
  for (const CaseOutcome* c : cases)
    if (c->outcome != ImpactOutcome::undetermined) determined.push_back(c);
  return determined;
}

std::size_t small_strain_count(const std::vector<const CaseOutcome*>& cases) {
  std::size_t count = 0;
  for (const CaseOutcome* c : cases) count += c->small_strain_exceeded ? 1 : 0;
  return count;
}

}  // namespace aerobreak
