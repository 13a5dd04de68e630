#pragma once
#include <vector>

#include "orchestrator/fitting/case_groups.hpp"
#include "orchestrator/fitting/correlation_set.hpp"

namespace aerobreak {

// Retained mass fraction against log impact speed, per group: the fractional logit of Papke &
// Wooldridge (1996), E[f] = logistic(b0 + b1 log v), fitted by the binomial estimating equations
// with one row per case; the dispersion phi = Pearson X^2 / (n - 2) scales the covariance
// (quasi-binomial: McCullagh & Nelder, sec. 9.2.4).
std::vector<RetainedFractionFit> fit_retained_fractions(const CaseOutcomeTable& table,
                                                        const std::vector<CaseGroup>& groups,
                                                        const CorrelationRequest& request);

// log v_p = a + sum_k b_k log(axis_k) over the groups whose speed fit gave v_p with a bounded
// interval, by weighted least squares with weights 1 / s_i^2, s_i = (ln hi - ln lo) / (2 x 1.96);
// standard errors scaled by sqrt(max(1, chi^2/df)) (the Birge ratio) when the scatter exceeds the
// intervals. One fit per response and condition (condition_groups: scaling.OUTCOME.v50.cK): the
// axes are the modelled ones (the request's covariates) that are numeric, positive and vary among
// the condition's groups; every other axis splits the conditions. None without covariates.
std::vector<ScalingFit> fit_scaling_laws(const std::vector<LogisticFit>& logistic,
                                         const std::vector<CaseGroup>& conditions, const CorrelationRequest& request);

}  // namespace aerobreak
