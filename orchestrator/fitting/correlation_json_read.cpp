// A logistic fit read back from its stored document (fit_json): the lookup-table export evaluates
// the stored fits instead of fitting the study again. JSON keeps every double exactly (17
// significant digits), so that a fit read back predicts what the fit did.
#include <limits>
#include <stdexcept>

#include "orchestrator/fitting/correlation_json.hpp"

namespace aerobreak {
namespace {

double number_or_nan(const nlohmann::ordered_json& value) {
  return value.is_number() ? value.get<double>() : std::numeric_limits<double>::quiet_NaN();
}

std::optional<double> optional_number(const nlohmann::ordered_json& value) {
  return value.is_number() ? std::optional(value.get<double>()) : std::nullopt;
}

FitStatus status_of(const std::string& text) {
  for (const auto status : {FitStatus::ok, FitStatus::separation, FitStatus::insufficient_data,
                            FitStatus::no_transition, FitStatus::not_converged})
    if (to_string(status) == text) return status;
  throw std::runtime_error("unknown fit status '" + text + "'");
}

ImpactOutcome outcome_of(const std::string& text) {
  const auto outcome = parse_outcome(text);
  if (!outcome) throw std::runtime_error("unknown outcome '" + text + "'");
  return *outcome;
}

void read_common(FitCommon& common, const nlohmann::ordered_json& document) {
  common.name = document.at("name");
  common.kind = document.at("kind");
  common.status = status_of(document.at("status"));
  common.detail = document.at("detail");
  common.group = document.at("group");
  const auto& parameters = document.at("parameters");
  common.coefficients.resize(static_cast<Eigen::Index>(parameters.size()));
  for (std::size_t j = 0; j < parameters.size(); ++j) {
    common.parameters.push_back(parameters[j].at("name"));
    common.coefficients[static_cast<Eigen::Index>(j)] = parameters[j].at("estimate").get<double>();
  }
  const auto& covariance = document.at("covariance");
  common.covariance.resize(static_cast<Eigen::Index>(covariance.size()), static_cast<Eigen::Index>(covariance.size()));
  for (std::size_t i = 0; i < covariance.size(); ++i)
    for (std::size_t j = 0; j < covariance[i].size(); ++j)
      common.covariance(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = number_or_nan(covariance[i][j]);
  common.cases = document.at("cases");
  common.groups = document.at("groups");
  common.small_strain_cases = document.at("small_strain").at("cases");
  for (const auto& [input, range] : document.at("validity").items())
    common.validity.push_back({input, range.at("min"), range.at("max")});
}

}  // namespace

LogisticFit logistic_fit_from_json(const nlohmann::ordered_json& document) {
  LogisticFit fit;
  read_common(fit.common, document);
  fit.response = outcome_of(document.at("response"));
  fit.dose = document.at("dose");
  fit.method = document.at("method");
  for (const auto& covariate : document.at("covariates"))
    fit.covariates.push_back({covariate.at("axis"), covariate.at("transform") == "log"});
  for (const auto& value : document.at("critical"))
    fit.critical.push_back({value.at("level"), value.at("at"), optional_number(value.at("estimate")),
                            optional_number(value.at("ci95")[0]), optional_number(value.at("ci95")[1])});
  for (const auto& value : document.value("observed_crossings", nlohmann::ordered_json::array()))
    fit.observed.push_back({value.at("level"), nlohmann::ordered_json::object(), optional_number(value.at("dose")),
                            std::nullopt, std::nullopt});
  const auto& data = document.at("data");
  fit.data.trials.resize(static_cast<Eigen::Index>(data.size()));
  fit.data.successes.resize(static_cast<Eigen::Index>(data.size()));
  for (std::size_t i = 0; i < data.size(); ++i) {
    fit.data.trials[static_cast<Eigen::Index>(i)] = data[i].at("trials").get<double>();
    fit.data.successes[static_cast<Eigen::Index>(i)] = data[i].at("successes").get<double>();
  }
  return fit;
}

}  // namespace aerobreak
