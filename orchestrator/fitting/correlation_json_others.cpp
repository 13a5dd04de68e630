// The summary line and the full document of the multinomial, scaling, retained-fraction and
// fragment-size fits.
#include <algorithm>
#include <cmath>
#include <map>

#include "orchestrator/fitting/correlation_json_parts.hpp"

namespace aerobreak {
namespace {

nlohmann::ordered_json band(const BandPoint& point) {
  return {{"value", point.probability}, {"ci95", {point.lower, point.upper}}};
}

}  // namespace

nlohmann::ordered_json summary_line(const MultinomialFit& fit) {
  auto line = summary_common(fit.common);
  line["dose"] = fit.dose;
  return line;
}

nlohmann::ordered_json full_json(const MultinomialFit& fit, int points) {
  auto json = common_json(fit.common);
  json["dose"] = fit.dose;
  json["model"] = "log(P_k / P_stick) = a_k + b_k log(impact_speed), k = bounce, break-up";
  nlohmann::ordered_json data = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < fit.doses.size(); ++i)
    data.push_back({{"dose", fit.doses[i]},
                    {"stick", fit.counts[i][0]},
                    {"bounce", fit.counts[i][1]},
                    {"break-up", fit.counts[i][2]}});
  json["data"] = data;
  nlohmann::ordered_json curve = nlohmann::ordered_json::array();
  if (fit.common.coefficients.size() > 0)
    for (const double dose : log_spaced(fit.doses.front(), fit.doses.back(), points)) {
      const auto bands = fit.probabilities(dose);
      curve.push_back(
          {{"dose", dose}, {"stick", band(bands[0])}, {"bounce", band(bands[1])}, {"break-up", band(bands[2])}});
    }
  json["curve"] = curve;
  return json;
}

nlohmann::ordered_json summary_line(const ScalingFit& fit) {
  auto line = summary_common(fit.common);
  line["response"] = std::string(to_string(fit.response));
  line["level"] = fit.level;
  line["pooled_over"] = fit.axes;
  nlohmann::ordered_json exponents = nlohmann::ordered_json::object();
  for (std::size_t k = 0; k < fit.axes.size() && fit.common.coefficients.size() > 0; ++k) {
    const auto j = static_cast<Eigen::Index>(k + 1);
    const double se = std::sqrt(fit.common.covariance(j, j));
    exponents[fit.axes[k]] = {
        {"estimate", fit.common.coefficients[j]},
        {"ci95", {fit.common.coefficients[j] - kZ95 * se, fit.common.coefficients[j] + kZ95 * se}}};
  }
  line["exponents"] = exponents;
  return line;
}

nlohmann::ordered_json full_json(const ScalingFit& fit, int) {
  auto json = common_json(fit.common);
  json["response"] = std::string(to_string(fit.response));
  json["level"] = fit.level;
  json["model"] = "log v = log(prefactor) + sum_k exponent_k log(axis_k), weighted by the v intervals";
  json["axes"] = fit.axes;
  json["scale_factor"] = fit.scale_factor;
  nlohmann::ordered_json data = nlohmann::ordered_json::array();
  for (const auto& point : fit.points) {
    nlohmann::ordered_json row{
        {"group", point.group}, {"critical_speed", point.critical_speed}, {"ci95", {point.lower, point.upper}}};
    if (fit.common.coefficients.size() > 0) {
      Eigen::VectorXd x(fit.common.coefficients.size());
      x[0] = 1.0;
      for (std::size_t k = 0; k < fit.axes.size(); ++k)
        x[static_cast<Eigen::Index>(k + 1)] = std::log(point.group.at(fit.axes[k]).get<double>());
      const double se = std::sqrt(std::max(0.0, x.dot(fit.common.covariance * x)));
      row["fitted"] = {{"value", std::exp(x.dot(fit.common.coefficients))},
                       {"ci95",
                        {std::exp(x.dot(fit.common.coefficients) - kZ95 * se),
                         std::exp(x.dot(fit.common.coefficients) + kZ95 * se)}}};
    }
    data.push_back(row);
  }
  json["data"] = data;
  return json;
}

nlohmann::ordered_json summary_line(const RetainedFractionFit& fit) {
  auto line = summary_common(fit.common);
  line["dispersion"] = fit.dispersion;
  return line;
}

nlohmann::ordered_json full_json(const RetainedFractionFit& fit, int points) {
  auto json = common_json(fit.common);
  json["model"] = "E[retained mass fraction] = logistic(b0 + b1 log(impact_speed)), quasi-binomial";
  json["dispersion"] = fit.dispersion;
  std::map<double, std::vector<double>> by_speed;
  for (Eigen::Index i = 0; i < fit.data.design.rows(); ++i)
    by_speed[std::exp(fit.data.design(i, 1))].push_back(fit.data.successes[i]);
  nlohmann::ordered_json data = nlohmann::ordered_json::array();
  for (const auto& [speed, fractions] : by_speed) {
    data.push_back({{"dose", speed}, {"retained_mass_fraction", mean_json(mean_estimate(fractions))}});
  }
  json["data"] = data;
  nlohmann::ordered_json curve = nlohmann::ordered_json::array();
  if (fit.common.coefficients.size() > 0)
    for (const double speed : log_spaced(fit.common.validity[0].min, fit.common.validity[0].max, points)) {
      auto point = band(fit.mean_fraction(speed));
      point["dose"] = speed;
      curve.push_back(point);
    }
  json["curve"] = curve;
  return json;
}

nlohmann::ordered_json full_json(const FragmentSizeFit& fit, int) {
  auto json = common_json(fit.common);
  json["largest_size"] = fit.largest_size;
  nlohmann::ordered_json histogram = nlohmann::ordered_json::array();
  for (const auto& [size, count] : fit.histogram) histogram.push_back({{"size", size}, {"count", count}});
  json["data"] = histogram;
  if (fit.common.status != FitStatus::ok) return json;
  json["power_law"] = {
      {"model", "P(s) = s^-tau / sum_{t=1..N} t^-tau"},  {"tau", fit.exponent},
      {"standard_error", fit.exponent_standard_error},   {"log_likelihood", fit.power_law_log_likelihood},
      {"aic", 2.0 - 2.0 * fit.power_law_log_likelihood}, {"ks_distance", fit.power_law_ks}};
  json["lognormal"] = {
      {"model", "P(s) = [Phi((ln(s+1/2) - mu)/sigma) - Phi((ln(s-1/2) - mu)/sigma)] / Z on 1..N"},
      {"mu", fit.mu},
      {"sigma", fit.sigma},
      {"standard_errors", {std::sqrt(fit.lognormal_covariance(0, 0)), std::sqrt(fit.lognormal_covariance(1, 1))}},
      {"log_likelihood", fit.lognormal_log_likelihood},
      {"aic", 4.0 - 2.0 * fit.lognormal_log_likelihood},
      {"ks_distance", fit.lognormal_ks}};
  json["vuong"] = {{"statistic", fit.vuong_statistic},
                   {"p_value", fit.vuong_p_value},
                   {"favours", fit.vuong_statistic > 0 ? "lognormal" : "power law"}};
  return json;
}

}  // namespace aerobreak
