#include "orchestrator/fitting/correlation_set.hpp"

#include <chrono>
#include <cmath>

#include "orchestrator/fitting/case_groups.hpp"
#include "orchestrator/fitting/fragment_sizes.hpp"
#include "orchestrator/fitting/grid_aggregates.hpp"
#include "orchestrator/fitting/logistic_models.hpp"
#include "orchestrator/fitting/multinomial_logit.hpp"
#include "orchestrator/fitting/secondary_fits.hpp"

namespace aerobreak {

std::string_view to_string(FitStatus status) {
  switch (status) {
    case FitStatus::ok:
      return "ok";
    case FitStatus::separation:
      return "separation";
    case FitStatus::insufficient_data:
      return "insufficient-data";
    case FitStatus::no_transition:
      return "no-transition";
    case FitStatus::not_converged:
      break;
  }
  return "not-converged";
}

std::optional<double> observed_crossing(const std::vector<std::pair<double, double>>& points, double level) {
  for (std::size_t i = 1; i < points.size(); ++i) {
    const auto [x0, y0] = points[i - 1];
    const auto [x1, y1] = points[i];
    if ((y0 - level) * (y1 - level) > 0.0 || y0 == y1) continue;
    if (y0 == level) return x0;
    const double t = (level - y0) / (y1 - y0);
    return std::exp(std::log(x0) + t * (std::log(x1) - std::log(x0)));
  }
  return std::nullopt;
}

CorrelationSet compute_correlations(const CaseOutcomeTable& table, const CorrelationRequest& request,
                                    const Provenance& provenance) {
  const auto started = std::chrono::steady_clock::now();
  CorrelationSet set;
  set.provenance = provenance;
  set.request = request;
  set.grid_points = summarise_grid_points(table);
  const auto groups = group_cases(table, request.speed_axis);
  set.logistic = fit_logistic_models(table, groups, request);
  set.multinomial = fit_multinomial_models(table, groups, request);
  set.scaling = fit_scaling_laws(set.logistic, condition_groups(table, request), request);
  set.retained_fraction = fit_retained_fractions(table, groups, request);
  set.fragment_sizes = fit_fragment_distributions(table);
  set.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return set;
}

}  // namespace aerobreak
