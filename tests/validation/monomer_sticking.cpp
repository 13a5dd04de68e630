#include "tests/validation/monomer_sticking.hpp"

#include <cmath>
#include <numbers>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "engine/impact/impact_case.hpp"
#include "engine/impact/impact_run.hpp"

namespace aerobreak::validation {

namespace {

// One primary, undamped JKR without friction, a head-on impact at `speed` (m/s).
nlohmann::ordered_json monomer_case(const MaterialSI& material, double diameter, double speed) {
  return {{"units", "physical"},
          {"cluster", {{"generator", {{"method", "ballistic"}, {"primaries", 1}, {"seed", 1}}}}},
          {"material",
           {{"youngs_modulus", material.youngs_modulus},
            {"poisson_ratio", material.poisson_ratio},
            {"density", material.density},
            {"surface_energy", material.surface_energy},
            {"diameter", diameter}}},
          {"model",
           {{"normal", "jkr"}, {"separation", "displacement"}, {"damping", {{"law", "none"}}}, {"tangential", false}}},
          {"impact", {{"speed", speed}}},
          {"run", {{"time_limit", 1e9}}}};  // a placeholder, longer than any approach: monomer_sticks sets the limit
}

}  // namespace

bool monomer_sticks(const MaterialSI& material, double diameter, double speed) {
  nlohmann::ordered_json c = monomer_case(material, diameter, speed);
  const double approach = 0.01 / parse_impact_case(c).speed;  // tau, from the 0.01 d gap
  // Near the sticking speed the sphere leaves (or swings in the well) slowly: a longer limit then.
  for (double settle_time : {2000.0, 20000.0, 200000.0}) {
    c["run"]["time_limit"] = approach + settle_time;
    const ImpactResult result = run_impact(parse_impact_case(c));
    if (result.classification.outcome == ImpactOutcome::stick) return true;
    if (result.classification.outcome == ImpactOutcome::bounce) return false;
  }
  throw std::runtime_error("a monomer impact neither stuck nor bounced within 200 000 tau");
}

double monomer_sticking_speed(const MaterialSI& material, double diameter, double tolerance) {
  const double exact = exact_monomer_sticking_speed(material, diameter);
  double low = 0.5 * exact, high = 2.0 * exact;
  if (!monomer_sticks(material, diameter, low) || monomer_sticks(material, diameter, high))
    throw std::runtime_error("sticking speed not bracketed by [0.5, 2] times the closed form");
  while (high - low > tolerance * low) {
    const double middle = std::sqrt(low * high);
    (monomer_sticks(material, diameter, middle) ? low : high) = middle;
  }
  return std::sqrt(low * high);
}

double exact_monomer_sticking_speed(const MaterialSI& material, double diameter) {
  const double pi = std::numbers::pi;
  const double radius = 0.5 * diameter;  // R* at a wall
  const double modulus = material.youngs_modulus / (2.0 * (1.0 - material.poisson_ratio * material.poisson_ratio));
  const double work = 2.0 * material.surface_energy;
  const double a0 = std::cbrt(9.0 * pi * work * radius * radius / (2.0 * modulus));  // eq 4
  const double pull_off = 1.5 * pi * work * radius;                                  // eq 5
  const double critical_overlap = a0 * a0 / (2.0 * std::cbrt(6.0) * radius);         // eq 3
  const double loop_energy = 0.93550 * pull_off * critical_overlap;
  const double mass = material.density * pi * diameter * diameter * diameter / 6.0;
  return std::sqrt(2.0 * loop_energy / mass);
}

double log_log_slope(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    const double lx = std::log(x[k]), ly = std::log(y[k]);
    sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace aerobreak::validation
