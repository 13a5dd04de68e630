#pragma once
#include <Eigen/Dense>
#include <array>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "orchestrator/fitting/binomial_glm.hpp"
#include "orchestrator/fitting/case_outcome.hpp"
#include "orchestrator/fitting/correlation_request.hpp"
#include "orchestrator/fitting/mean_estimate.hpp"

// The table model of a study's correlations (docs/CORRELATIONS.md): per-grid-point aggregates and
// every fitted model, as plain structs for the lookup-table export and the JSON of the REST API.
namespace aerobreak {

// --- Per grid point -----------------------------------------------------------------------------

// Re-entrained fragments at one grid point. The units of the uncertainties are the cases: the
// fragments of one case are not independent of each other.
struct FragmentStatistics {
  std::size_t fragments = 0;                           // re-entrained fragments, all cases
  std::optional<MeanEstimate> monomer_fraction;        // monomers / fragments (ratio over cases)
  std::optional<MeanEstimate> mean_size;               // primaries / fragments (ratio over cases)
  std::array<std::optional<MeanEstimate>, 4> moments;  // M_k = sum over a case's fragments of size^k, mean over cases
};

struct GridPointSummary {
  nlohmann::ordered_json grid_point;
  std::size_t cases = 0;  // with a result
  std::size_t undetermined = 0;
  std::size_t small_strain_exceeded = 0;
  std::array<std::size_t, 3> counts{};                               // stick, bounce, break-up
  std::array<std::optional<ProportionEstimate>, 3> probabilities{};  // among the determined cases
  std::optional<MeanEstimate> retained_mass_fraction;
  std::optional<MeanEstimate> restitution_of_bounces;
  std::optional<MeanEstimate> damage_ratio;
  std::optional<MeanEstimate> energy_per_contact;
  FragmentStatistics reentrained;
  std::size_t determined() const { return counts[0] + counts[1] + counts[2]; }
};

// --- Fits ---------------------------------------------------------------------------------------

enum class FitStatus { ok, separation, insufficient_data, no_transition, not_converged };
std::string_view to_string(FitStatus status);

struct InputRange {
  std::string input;
  double min = 0.0;
  double max = 0.0;
};

struct GoodnessOfFit {
  std::string statistic;  // "deviance", "pearson", "hosmer-lemeshow", "chi-square", "ks", ...
  double value = 0.0;
  std::optional<double> degrees_of_freedom;
  std::optional<double> p_value;
};

// What every fit carries.
struct FitCommon {
  std::string name;
  std::string kind;
  FitStatus status = FitStatus::ok;
  std::string detail;                                               // why, when the status is not ok
  nlohmann::ordered_json group = nlohmann::ordered_json::object();  // axis values; {} when pooled
  std::vector<std::string> parameters;
  Eigen::VectorXd coefficients;
  Eigen::MatrixXd covariance;
  std::optional<double> log_likelihood;
  std::optional<double> deviance;
  std::vector<GoodnessOfFit> goodness_of_fit;
  std::size_t cases = 0;
  std::size_t groups = 0;  // grid points (distinct covariate patterns) among them
  std::size_t small_strain_cases = 0;
  std::vector<InputRange> validity;
};

// A critical dose in dose units (speed, energy per contact) at one point of the covariates.
struct CriticalValue {
  double level = 0.5;
  nlohmann::ordered_json at = nlohmann::ordered_json::object();  // covariate values; {} for a group's fit
  std::optional<double> estimate;
  std::optional<double> lower;
  std::optional<double> upper;
};

// A probability with its pointwise 95 % band.
struct BandPoint {
  double probability = 0.0;
  double lower = 0.0;
  double upper = 0.0;
};

// logit P(response) = b0 + b1 log(dose) [+ covariates], per group or pooled.
struct LogisticFit {
  FitCommon common;
  ImpactOutcome response = ImpactOutcome::break_up;
  std::string dose;  // "impact_speed" | "energy_per_contact"
  std::vector<Covariate> covariates;
  std::string method;  // "maximum likelihood" | "Firth penalised likelihood"
  bool separation_complete = false;
  std::size_t perfectly_predicted = 0;
  std::optional<std::array<double, 2>> separation_bracket;  // doses between which the outcome switches
  std::vector<CriticalValue> critical;
  // Where the measured proportions cross each level (observed_crossing), for a group's fit to grouped
  // rows (dose = speed); the model-free companion of `critical` (no interval).
  std::vector<CriticalValue> observed;
  std::vector<nlohmann::ordered_json> covariate_points;  // the groups' covariate values (pooled)
  BinomialData data;                                     // the design the fit used: columns 1, log dose, covariates
  // P at a dose and covariate values (transformed as in the design), with the Wald band on the logit.
  BandPoint probability(double dose, const Eigen::VectorXd& covariates = {}) const;
};

// Baseline-category (multinomial) logit of stick / bounce / break-up in log dose (stick = baseline).
struct MultinomialFit {
  FitCommon common;
  std::string dose;
  std::vector<ImpactOutcome> categories;                      // the first is the baseline
  std::vector<double> doses;                                  // distinct doses of the data
  std::vector<std::vector<double>> counts;                    // per dose, per category
  std::array<BandPoint, 3> probabilities(double dose) const;  // per category, delta-method band
};

// log v_p = a + sum_k b_k log(axis_k), weighted by the v_p intervals.
struct ScalingPoint {
  nlohmann::ordered_json group;
  double critical_speed = 0.0;
  double lower = 0.0;
  double upper = 0.0;
};
struct ScalingFit {
  FitCommon common;
  ImpactOutcome response = ImpactOutcome::break_up;
  double level = 0.5;
  std::vector<std::string> axes;
  std::vector<ScalingPoint> points;
  double scale_factor = 1.0;  // sqrt(max(1, chi^2/df)) applied to the standard errors
};

// Retained mass fraction against log speed: fractional (quasi-binomial) logit.
struct RetainedFractionFit {
  FitCommon common;
  double dispersion = 1.0;
  BinomialData data;
  BandPoint mean_fraction(double speed) const;
};

// Re-entrained fragment sizes at one grid point: a discrete power law and a discretised
// lognormal, both on 1..N.
struct FragmentSizeFit {
  FitCommon common;
  std::int64_t largest_size = 0;                                // N: the upper end of both distributions
  std::vector<std::pair<std::int64_t, std::size_t>> histogram;  // size, count
  double exponent = 0.0, exponent_standard_error = 0.0;         // tau of P(s) ~ s^-tau
  double power_law_log_likelihood = 0.0, power_law_ks = 0.0;
  double mu = 0.0, sigma = 0.0;  // of ln s
  Eigen::Matrix2d lognormal_covariance = Eigen::Matrix2d::Zero();
  double lognormal_log_likelihood = 0.0, lognormal_ks = 0.0;
  double vuong_statistic = 0.0, vuong_p_value = 1.0;  // > 0 favours the lognormal
};

struct CorrelationSet {
  Provenance provenance;
  CorrelationRequest request;
  std::vector<GridPointSummary> grid_points;
  std::vector<LogisticFit> logistic;
  std::vector<MultinomialFit> multinomial;
  std::vector<ScalingFit> scaling;
  std::vector<RetainedFractionFit> retained_fraction;
  std::vector<FragmentSizeFit> fragment_sizes;
  double seconds = 0.0;  // time taken by compute_correlations
};

// Where measured proportions, (dose, proportion) in ascending dose, first cross `level`, interpolated
// linearly in log dose between the two points around it; nullopt when they never do. The one
// definition of the measured crossing: the service serves it with each group's fit and the
// dashboard and the analysis script read it there.
std::optional<double> observed_crossing(const std::vector<std::pair<double, double>>& points, double level);

// Everything, from a study's outcomes: pure, no I/O.
CorrelationSet compute_correlations(const CaseOutcomeTable& table, const CorrelationRequest& request,
                                    const Provenance& provenance);

}  // namespace aerobreak
