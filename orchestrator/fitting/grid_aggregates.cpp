#include "orchestrator/fitting/grid_aggregates.hpp"

#include <cmath>

#include "orchestrator/fitting/case_groups.hpp"

namespace aerobreak {
namespace {

std::optional<MeanEstimate> mean_of(const std::vector<const CaseOutcome*>& cases,
                                    std::optional<double> CaseOutcome::*field, std::optional<ImpactOutcome> only = {}) {
  std::vector<double> values;
  for (const CaseOutcome* c : cases)
    if ((!only || c->outcome == *only) && c->*field) values.push_back(*(c->*field));
  return mean_estimate(values);
}

GridPointSummary summarise(const nlohmann::ordered_json& grid_point, const std::vector<const CaseOutcome*>& cases) {
  GridPointSummary summary;
  summary.grid_point = grid_point;
  summary.cases = cases.size();
  for (const CaseOutcome* c : cases) {
    if (c->small_strain_exceeded) ++summary.small_strain_exceeded;
    if (c->outcome == ImpactOutcome::undetermined)
      ++summary.undetermined;
    else
      ++summary.counts[static_cast<std::size_t>(c->outcome)];
  }
  for (std::size_t k = 0; k < 3; ++k)
    summary.probabilities[k] = wilson_interval(summary.counts[k], summary.determined());
  // Undetermined cases are left out of every mean: their state is not final.
  const auto determined = determined_cases(cases);
  summary.retained_mass_fraction = mean_of(determined, &CaseOutcome::retained_mass_fraction);
  summary.restitution_of_bounces = mean_of(determined, &CaseOutcome::restitution, ImpactOutcome::bounce);
  summary.damage_ratio = mean_of(determined, &CaseOutcome::damage_ratio);
  summary.energy_per_contact = mean_of(cases, &CaseOutcome::energy_per_contact);
  summary.reentrained = fragment_statistics(determined);
  return summary;
}

}  // namespace

FragmentStatistics fragment_statistics(const std::vector<const CaseOutcome*>& cases) {
  FragmentStatistics statistics;
  std::vector<double> fragments, monomers, primaries;
  std::array<std::vector<double>, 4> moments;
  for (const CaseOutcome* c : cases) {
    std::array<double, 4> m{};
    double singles = 0.0;
    for (const auto size : c->reentrained_sizes) {
      const double s = static_cast<double>(size);
      for (std::size_t k = 0; k < 4; ++k) m[k] += std::pow(s, static_cast<double>(k));
      if (size == 1) singles += 1.0;
    }
    statistics.fragments += c->reentrained_sizes.size();
    fragments.push_back(m[0]);
    monomers.push_back(singles);
    primaries.push_back(m[1]);
    for (std::size_t k = 0; k < 4; ++k) moments[k].push_back(m[k]);
  }
  statistics.monomer_fraction = ratio_estimate(monomers, fragments);
  statistics.mean_size = ratio_estimate(primaries, fragments);
  for (std::size_t k = 0; k < 4; ++k) statistics.moments[k] = mean_estimate(moments[k]);
  return statistics;
}

std::vector<GridPointSummary> summarise_grid_points(const CaseOutcomeTable& table) {
  const auto by_point = cases_by_point(table);
  std::vector<GridPointSummary> summaries;
  summaries.reserve(table.grid_points.size());
  for (std::size_t g = 0; g < table.grid_points.size(); ++g)
    summaries.push_back(summarise(table.grid_points[g], by_point[g]));
  return summaries;
}

}  // namespace aerobreak
