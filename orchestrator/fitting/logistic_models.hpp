#pragma once
#include <string>
#include <vector>

#include "orchestrator/fitting/case_groups.hpp"
#include "orchestrator/fitting/correlation_set.hpp"

namespace aerobreak {

// The rows one logistic model is fitted to, with what its validity box and provenance need.
struct DoseData {
  BinomialData binomial;                          // columns: 1, log dose, covariate terms
  std::vector<double> dose;                       // per row, in dose units
  std::vector<Eigen::VectorXd> covariate_values;  // per row, untransformed
  std::vector<double> trials;                     // per row
  std::vector<double> successes;                  // per row
  std::size_t cases = 0;
  std::size_t small_strain = 0;
  std::size_t groups = 0;  // grid points that contributed
};

// Grouped rows, one per grid point with determined cases: trials = determined cases, successes =
// cases of `response`. Dose = the speed axis's value.
DoseData speed_rows(const CaseOutcomeTable& table, const std::vector<std::size_t>& grid_points, ImpactOutcome response,
                    const CorrelationRequest& request);
// The same with the cases already indexed by grid point (cases_by_point).
DoseData speed_rows(const CaseOutcomeTable& table, const std::vector<std::vector<const CaseOutcome*>>& by_point,
                    const std::vector<std::size_t>& grid_points, ImpactOutcome response,
                    const CorrelationRequest& request);
// One row per determined case with a positive energy per contact (dose = E_kin / (N_c E_break)).
DoseData energy_rows(const CaseOutcomeTable& table, const std::vector<const CaseOutcome*>& cases,
                     ImpactOutcome response, const CorrelationRequest& request);

// The logistic model of one data set: ML; under separation Firth's penalised likelihood with the
// separation reported; too few distinct doses or no transition reported as such, without a fit.
// Critical doses at `levels` by profile likelihood, at each of `covariate_points` (pooled models)
// or at the group itself (none).
LogisticFit fit_logistic(FitCommon common, ImpactOutcome response, const std::string& dose, const DoseData& rows,
                         const CorrelationRequest& request, const std::vector<Eigen::VectorXd>& covariate_points);

// All logistic models of a study: P(stick), P(bounce), P(break-up) (those that occur), in log impact
// speed and in log energy per contact; per group (OUTCOME.DOSE.gK, no covariate) and, per condition
// whose groups differ in a covariate (condition_groups), pooled along the covariates that vary in it
// (OUTCOME.DOSE.pooled.cK: e.g. logit P = b0 + b1 log v + b2 log N for one wall and one gamma/k_n),
// their critical doses at each of the condition's covariate values (delta method).
std::vector<LogisticFit> fit_logistic_models(const CaseOutcomeTable& table, const std::vector<CaseGroup>& groups,
                                             const CorrelationRequest& request);

}  // namespace aerobreak
