#pragma once
#include <Eigen/Dense>
#include <optional>
#include <string>
#include <vector>

#include "orchestrator/fitting/binomial_glm.hpp"
#include "orchestrator/search/boundary_search.hpp"

namespace aerobreak {

// How the outcomes of one response lie along the dose: both seen at overlapping doses (a maximum
// likelihood fit may exist), all of one class below all of the other (separated: the gap between
// them is where the crossing is), only one class, or no result.
enum class Overlap { overlapping, separated, one_outcome, no_data };

// The logistic model logit P(response) = b0 + b1 dose of one group, fitted to its results grouped
// by value by Firth's penalised likelihood (the correlations' binomial GLM, orchestrator/fitting/).
// Always Firth's, never plain maximum likelihood: it exists under separation, its bias is
// O(1/n^2) instead of O(1/n) on the searches' small samples, and its profile intervals held the
// nominal coverage where maximum likelihood's fell short (docs/ADAPTIVE.md, "The fit and the
// interval"); one estimator for every round also keeps the decisions free of a switch between two.
struct ResponseFit {
  std::string response;
  BinomialData data;  // one row per distinct value: design (1, dose - search_centre)
  Overlap overlap = Overlap::no_data;
  double gap_low = 0.0, gap_high = 0.0;  // doses bounding the gap when separated
  std::optional<GlmFit> fit;             // Firth's; none when its iterations did not converge
};

// The fit of `response` to the observations (sorted by value; undetermined ones left out).
ResponseFit fit_response(const BoundarySearchSpec& spec, const std::vector<SearchObservation>& sorted,
                         const std::string& response);

// The crossing of `level` from a fit, with its profile-likelihood interval (critical_dose.hpp)
// searched over the range widened by its own span on each side; whether it is as narrow as asked.
CrossingEstimate crossing(const BoundarySearchSpec& spec, const ResponseFit& fit, double level);

// The middle of the range in dose units. Doses enter the fits centred on it: with log speeds near
// -3 the intercept and slope of an uncentred design are so correlated that the (Firth) Newton
// iterations crawl.
double search_centre(const BoundarySearchSpec& spec);

// The wanted half-width of a crossing's interval in dose units at the estimate `dose`.
double wanted_half_width(const BoundarySearchSpec& spec, double dose);

}  // namespace aerobreak
