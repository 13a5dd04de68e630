#pragma once
#include <vector>

#include "orchestrator/fitting/case_groups.hpp"
#include "orchestrator/fitting/correlation_set.hpp"

namespace aerobreak {

// The baseline-category (multinomial) logit of the three outcomes against log impact speed, per
// group where all three occur (Agresti, Categorical Data Analysis, 3rd ed., sec. 8.1): with stick
// as the baseline, log(P_k / P_stick) = a_k + b_k log v for k = bounce, break-up, by Newton on the
// multinomial log-likelihood. Chosen over an ordinal (cumulative logit) model because it assumes no
// order of the outcomes along the speed, which oblique or non-adhesive impacts need not keep.
// Under separation no estimate exists; the fit says so and leaves the coefficients empty (the
// binomial fits of the same group give Firth estimates).
std::vector<MultinomialFit> fit_multinomial_models(const CaseOutcomeTable& table, const std::vector<CaseGroup>& groups,
                                                   const CorrelationRequest& request);

// One multinomial fit of grouped counts (rows: doses; columns: stick, bounce, break-up).
MultinomialFit fit_multinomial(const std::vector<double>& doses, const std::vector<std::vector<double>>& counts);

}  // namespace aerobreak
