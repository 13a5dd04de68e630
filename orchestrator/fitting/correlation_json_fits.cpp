// The summary line and the full document of each kind of fit.
#include <algorithm>
#include <cmath>
#include <numeric>

#include "orchestrator/fitting/correlation_json_parts.hpp"

namespace aerobreak {
namespace {

// "y = b0 + b1 log(x) + ...": the model in words, from its parameter names.
std::string formula(const std::string& left, const std::vector<std::string>& parameters) {
  std::string text = left + " = b0";
  for (std::size_t j = 1; j < parameters.size(); ++j) text += " + b" + std::to_string(j) + " " + parameters[j];
  return text;
}

nlohmann::ordered_json critical_json(const CriticalValue& value) {
  return {{"level", value.level},
          {"at", value.at},
          {"estimate", number_or_null(value.estimate)},
          {"ci95", {number_or_null(value.lower), number_or_null(value.upper)}}};
}

// Where the measured proportions cross each level (a group's speed fit; [] otherwise).
nlohmann::ordered_json observed_json(const LogisticFit& fit) {
  nlohmann::ordered_json crossings = nlohmann::ordered_json::array();
  for (const auto& value : fit.observed)
    crossings.push_back({{"level", value.level}, {"dose", number_or_null(value.estimate)}});
  return crossings;
}

nlohmann::ordered_json band_json(double dose, const BandPoint& band) {
  return {{"dose", dose}, {"value", band.probability}, {"ci95", {band.lower, band.upper}}};
}

// The fitted rows, each with its observed proportion and Wilson interval (at most 1,000 rows: a fit
// to more single cases gives 20 bins of equal count instead).
nlohmann::ordered_json logistic_data_json(const LogisticFit& fit) {
  const auto& d = fit.data;
  const Eigen::Index rows = d.design.rows();
  const Eigen::Index per_bin = rows > 1000 ? (rows + 19) / 20 : 1;
  std::vector<Eigen::Index> order(static_cast<std::size_t>(rows));
  std::iota(order.begin(), order.end(), 0);
  if (per_bin > 1)
    std::stable_sort(order.begin(), order.end(),
                     [&d](Eigen::Index a, Eigen::Index b) { return d.design(a, 1) < d.design(b, 1); });
  nlohmann::ordered_json data = nlohmann::ordered_json::array();
  for (Eigen::Index start = 0; start < rows; start += per_bin) {
    double trials = 0.0, successes = 0.0, log_dose = 0.0;
    const Eigen::Index end = std::min(rows, start + per_bin);
    for (Eigen::Index r = start; r < end; ++r) {
      const Eigen::Index i = order[static_cast<std::size_t>(r)];
      trials += d.trials[i];
      successes += d.successes[i];
      log_dose += d.design(i, 1) / static_cast<double>(end - start);
    }
    const auto wilson = wilson_interval(static_cast<std::size_t>(successes), static_cast<std::size_t>(trials));
    nlohmann::ordered_json row{{"dose", std::exp(log_dose)},
                               {"trials", trials},
                               {"successes", successes},
                               {"proportion", wilson->probability},
                               {"ci95", {wilson->lower, wilson->upper}}};
    for (Eigen::Index k = 2; k < d.design.cols() && per_bin == 1; ++k) {
      const Covariate& covariate = fit.covariates[static_cast<std::size_t>(k - 2)];
      row[covariate.axis] = covariate.logarithmic ? std::exp(d.design(order[static_cast<std::size_t>(start)], k))
                                                  : d.design(order[static_cast<std::size_t>(start)], k);
    }
    data.push_back(row);
  }
  return data;
}

nlohmann::ordered_json logistic_curves_json(const LogisticFit& fit, int points) {
  nlohmann::ordered_json curves = nlohmann::ordered_json::array();
  if (fit.common.coefficients.size() == 0 || fit.common.validity.empty()) return curves;
  const auto grid = log_spaced(fit.common.validity[0].min, fit.common.validity[0].max, points);
  std::vector<nlohmann::ordered_json> ats;
  for (const auto& value : fit.critical)
    if (ats.empty() || ats.back() != value.at) ats.push_back(value.at);
  for (const auto& at : ats) {
    Eigen::VectorXd covariates(static_cast<Eigen::Index>(fit.covariates.size()));
    for (std::size_t k = 0; k < fit.covariates.size(); ++k)
      covariates[static_cast<Eigen::Index>(k)] = at.at(fit.covariates[k].axis).get<double>();
    nlohmann::ordered_json curve = nlohmann::ordered_json::array();
    for (const double dose : grid) curve.push_back(band_json(dose, fit.probability(dose, covariates)));
    curves.push_back({{"at", at}, {"points", curve}});
  }
  return curves;
}

}  // namespace

nlohmann::ordered_json summary_line(const LogisticFit& fit) {
  auto line = summary_common(fit.common);
  line["response"] = std::string(to_string(fit.response));
  line["dose"] = fit.dose;
  line["method"] = fit.method;
  line["coefficients"] = std::vector<double>(fit.common.coefficients.data(),
                                             fit.common.coefficients.data() + fit.common.coefficients.size());
  nlohmann::ordered_json pooled_over = nlohmann::ordered_json::array();
  for (const auto& covariate : fit.covariates) pooled_over.push_back(covariate.axis);
  line["pooled_over"] = pooled_over;
  // A pooled model's critical values (one set per group's covariates) are in its full document only.
  nlohmann::ordered_json critical = nlohmann::ordered_json::array();
  for (const auto& value : fit.critical)
    if (value.at.empty()) critical.push_back(critical_json(value));
  line["critical"] = critical;
  line["observed_crossings"] = observed_json(fit);
  return line;
}

nlohmann::ordered_json full_json(const LogisticFit& fit, int points) {
  auto json = common_json(fit.common);
  json["response"] = std::string(to_string(fit.response));
  json["dose"] = fit.dose;
  json["model"] = formula("logit P(" + std::string(to_string(fit.response)) + ")", fit.common.parameters);
  json["method"] = fit.method;
  nlohmann::ordered_json covariates = nlohmann::ordered_json::array();
  for (const auto& covariate : fit.covariates)
    covariates.push_back({{"axis", covariate.axis}, {"transform", covariate.logarithmic ? "log" : "linear"}});
  json["covariates"] = covariates;
  json["separation"] =
      fit.common.status != FitStatus::separation
          ? nlohmann::ordered_json(nullptr)
          : nlohmann::ordered_json{{"complete", fit.separation_complete},
                                   {"perfectly_predicted_rows", fit.perfectly_predicted},
                                   {"bracket", fit.separation_bracket ? nlohmann::ordered_json(*fit.separation_bracket)
                                                                      : nlohmann::ordered_json(nullptr)}};
  nlohmann::ordered_json critical = nlohmann::ordered_json::array();
  for (const auto& value : fit.critical) critical.push_back(critical_json(value));
  json["critical"] = critical;
  json["observed_crossings"] = observed_json(fit);
  json["data"] = logistic_data_json(fit);
  json["curves"] = logistic_curves_json(fit, points);
  return json;
}

}  // namespace aerobreak
