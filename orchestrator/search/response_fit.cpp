#include "orchestrator/search/response_fit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "orchestrator/fitting/critical_dose.hpp"

namespace aerobreak {
namespace {

BinomialData grouped_rows(const BoundarySearchSpec& spec, const std::vector<SearchObservation>& sorted,
                          const std::string& response) {
  std::vector<double> doses, trials, successes;
  for (const auto& o : sorted) {
    if (o.outcome == "undetermined") continue;
    const double dose = search_dose(spec, o.value) - search_centre(spec);
    if (doses.empty() || doses.back() != dose) {
      doses.push_back(dose);
      trials.push_back(0.0);
      successes.push_back(0.0);
    }
    trials.back() += 1.0;
    successes.back() += o.outcome == response ? 1.0 : 0.0;
  }
  BinomialData data;
  const auto n = static_cast<Eigen::Index>(doses.size());
  data.design.resize(n, 2);
  data.trials.resize(n);
  data.successes.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    data.design(i, 0) = 1.0;
    data.design(i, 1) = doses[static_cast<std::size_t>(i)];
    data.trials[i] = trials[static_cast<std::size_t>(i)];
    data.successes[i] = successes[static_cast<std::size_t>(i)];
  }
  return data;
}

// In one dimension separation is plain to see: every dose with a success lies beyond every dose
// with a failure (or the other way round).
void classify_overlap(ResponseFit& fit) {
  const auto& d = fit.data;
  double success_low = INFINITY, success_high = -INFINITY, failure_low = INFINITY, failure_high = -INFINITY;
  for (Eigen::Index i = 0; i < d.trials.size(); ++i) {
    const double dose = d.design(i, 1);
    if (d.successes[i] > 0.0) success_low = std::min(success_low, dose), success_high = std::max(success_high, dose);
    if (d.successes[i] < d.trials[i])
      failure_low = std::min(failure_low, dose), failure_high = std::max(failure_high, dose);
  }
  if (d.trials.size() == 0) {
    fit.overlap = Overlap::no_data;
  } else if (!std::isfinite(success_low) || !std::isfinite(failure_low)) {
    fit.overlap = Overlap::one_outcome;
  } else if (success_high < failure_low) {
    fit.overlap = Overlap::separated;
    fit.gap_low = success_high, fit.gap_high = failure_low;
  } else if (failure_high < success_low) {
    fit.overlap = Overlap::separated;
    fit.gap_low = failure_high, fit.gap_high = success_low;
  } else {
    fit.overlap = Overlap::overlapping;
  }
}

std::string overlap_text(Overlap overlap) {
  switch (overlap) {
    case Overlap::overlapping:
      return "overlapping";
    case Overlap::separated:
      return "separated";
    case Overlap::one_outcome:
      return "one outcome";
    case Overlap::no_data:
      return "no data";
  }
  return "no data";
}

}  // namespace

ResponseFit fit_response(const BoundarySearchSpec& spec, const std::vector<SearchObservation>& sorted,
                         const std::string& response) {
  ResponseFit out;
  out.response = response;
  out.data = grouped_rows(spec, sorted, response);
  classify_overlap(out);
  if (out.overlap != Overlap::overlapping && out.overlap != Overlap::separated) return out;
  // Firth's penalised likelihood (Firth 1993; finite under separation, Heinze & Schemper 2002).
  GlmOptions firth;
  firth.penalty = Penalty::firth;
  firth.max_iterations = 200;
  GlmFit penalised = fit_binomial(out.data, firth);
  if (penalised.converged && penalised.coefficients.allFinite()) out.fit = std::move(penalised);
  return out;
}

double search_centre(const BoundarySearchSpec& spec) {
  return 0.5 * (search_dose(spec, spec.from) + search_dose(spec, spec.to));
}

double wanted_half_width(const BoundarySearchSpec& spec, double dose) {
  // On the log scale the interval [d - h, d + h] is e^d 2 sinh(h) wide in axis units.
  double half = 0.0;
  if (spec.logarithmic) {
    if (spec.relative_width > 0.0) half = std::max(half, std::asinh(spec.relative_width / 2.0));
    if (spec.width > 0.0) half = std::max(half, std::asinh(spec.width / (2.0 * std::exp(dose))));
  } else {
    if (spec.relative_width > 0.0) half = std::max(half, spec.relative_width * std::abs(dose) / 2.0);
    if (spec.width > 0.0) half = std::max(half, spec.width / 2.0);
  }
  return half;
}

CrossingEstimate crossing(const BoundarySearchSpec& spec, const ResponseFit& fit, double level) {
  CrossingEstimate out;
  out.response = fit.response;
  out.level = level;
  out.status = overlap_text(fit.overlap);
  out.fit = fit.fit ? "firth" : "none";
  if (!fit.fit || fit.fit->coefficients[1] == 0.0) return out;
  const double centre = search_centre(spec);
  const double low = search_dose(spec, spec.from) - centre, high = search_dose(spec, spec.to) - centre;
  CriticalDoseRequest request;
  request.reference = Eigen::Vector2d(1.0, 0.0);
  request.dose_column = 1;
  request.level = level;
  request.search_low = low - (high - low);
  request.search_high = high + (high - low);
  request.penalty = Penalty::firth;
  const CriticalDose dose = critical_dose(fit.data, *fit.fit, request);
  if (!dose.estimate) return out;
  out.estimate = search_value(spec, *dose.estimate + centre);
  if (dose.lower) out.lower = search_value(spec, *dose.lower + centre);
  if (dose.upper) out.upper = search_value(spec, *dose.upper + centre);
  if (fit.overlap != Overlap::overlapping || !out.lower || !out.upper) return out;
  const double wide = *out.upper - *out.lower;
  out.narrow_enough = (spec.relative_width > 0.0 && wide <= spec.relative_width * std::abs(*out.estimate)) ||
                      (spec.width > 0.0 && wide <= spec.width);
  return out;
}

}  // namespace aerobreak
