#include "orchestrator/fitting/correlation_set.hpp"

#include <chrono>

#include "orchestrator/fitting/case_groups.hpp"
#include "orchestrator/fitting/fragment_sizes.hpp"
#include "orchestrator/fitting/grid_aggregates.hpp"
#include "orchestrator/fitting/logistic_models.hpp"
#include "orchestrator/fitting/multinomial_logit.hpp"
#include "orchestrator/fitting/secondary_fits.hpp"

namespace aerobreak {

std::string_view to_string(FitStatus status) {
  switch (status) {
    case FitStatus::ok: return "ok";
    case FitStatus::separation: return "separation";
    case FitStatus::insufficient_data: return "insufficient-data";
    case FitStatus::no_transition: return "no-transition";
    case FitStatus::not_converged: break;
  }
  return "not-converged";
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
