#include "orchestrator/fitting/correlation_json_parts.hpp"

#include <cmath>

namespace aerobreak {

std::vector<double> log_spaced(double low, double high, int count) {
  std::vector<double> grid;
  for (int i = 0; i < count; ++i)
    grid.push_back(i == 0 ? low : i == count - 1 ? high : low * std::pow(high / low, i / (count - 1.0)));
  return grid;
}

namespace {

nlohmann::ordered_json fragments_json(const FragmentStatistics& fragments) {
  nlohmann::ordered_json moments = nlohmann::ordered_json::array();
  for (const auto& moment : fragments.moments) moments.push_back(mean_json(moment));
  return {{"fragments", fragments.fragments},
          {"monomer_fraction", mean_json(fragments.monomer_fraction)},
          {"mean_size", mean_json(fragments.mean_size)},
          {"moments", moments}};
}

// Per input: {"min", "max"} over the rows the fit used.
nlohmann::ordered_json validity_json(const std::vector<InputRange>& box) {
  nlohmann::ordered_json validity = nlohmann::ordered_json::object();
  for (const auto& range : box) validity[range.input] = {{"min", range.min}, {"max", range.max}};
  return validity;
}

}  // namespace

nlohmann::ordered_json grid_point_json(const GridPointSummary& point) {
  nlohmann::ordered_json outcomes = nlohmann::ordered_json::object();
  for (std::size_t k = 0; k < 3; ++k)
    outcomes[std::string(to_string(kDeterminedOutcomes[k]))] = proportion_json(point.counts[k], point.probabilities[k]);
  return {{"grid_point", point.grid_point},
          {"cases", point.cases},
          {"determined", point.determined()},
          {"undetermined", point.undetermined},
          {"small_strain_exceeded", point.small_strain_exceeded},
          {"outcomes", outcomes},
          {"retained_mass_fraction", mean_json(point.retained_mass_fraction)},
          {"restitution_of_bounces", mean_json(point.restitution_of_bounces)},
          {"damage_ratio", mean_json(point.damage_ratio)},
          {"energy_per_contact", mean_json(point.energy_per_contact)},
          {"reentrained", fragments_json(point.reentrained)}};
}

nlohmann::ordered_json common_json(const FitCommon& common) {
  const bool fitted = common.coefficients.size() > 0;
  nlohmann::ordered_json parameters = nlohmann::ordered_json::array();
  nlohmann::ordered_json covariance = nlohmann::ordered_json::array();
  for (Eigen::Index j = 0; fitted && j < common.coefficients.size(); ++j) {
    const double se = std::sqrt(common.covariance(j, j));
    parameters.push_back(
        {{"name", common.parameters.at(static_cast<std::size_t>(j))},
         {"estimate", common.coefficients[j]},
         {"standard_error", number_or_null(se)},
         {"ci95",
          {number_or_null(common.coefficients[j] - kZ95 * se), number_or_null(common.coefficients[j] + kZ95 * se)}}});
    nlohmann::ordered_json row = nlohmann::ordered_json::array();
    for (Eigen::Index k = 0; k < common.covariance.cols(); ++k) row.push_back(number_or_null(common.covariance(j, k)));
    covariance.push_back(row);
  }
  nlohmann::ordered_json goodness = nlohmann::ordered_json::array();
  for (const auto& g : common.goodness_of_fit)
    goodness.push_back({{"statistic", g.statistic},
                        {"value", number_or_null(g.value)},
                        {"degrees_of_freedom", number_or_null(g.degrees_of_freedom)},
                        {"p_value", number_or_null(g.p_value)}});
  const double share =
      common.cases ? static_cast<double>(common.small_strain_cases) / static_cast<double>(common.cases) : 0.0;
  return {{"name", common.name},
          {"kind", common.kind},
          {"status", std::string(to_string(common.status))},
          {"detail", common.detail},
          {"group", common.group},
          {"parameters", parameters},
          {"covariance", covariance},
          {"log_likelihood", number_or_null(common.log_likelihood)},
          {"deviance", number_or_null(common.deviance)},
          {"goodness_of_fit", goodness},
          {"cases", common.cases},
          {"groups", common.groups},
          {"small_strain", {{"cases", common.small_strain_cases}, {"share", share}}},
          {"validity", validity_json(common.validity)}};
}

nlohmann::ordered_json summary_common(const FitCommon& common) {
  nlohmann::ordered_json line{
      {"name", common.name}, {"kind", common.kind}, {"status", std::string(to_string(common.status))}};
  if (!common.detail.empty()) line["detail"] = common.detail;
  line["group"] = common.group;
  line["cases"] = common.cases;
  line["validity"] = validity_json(common.validity);
  return line;
}

}  // namespace aerobreak
