#include "engine/growth/ornstein_uhlenbeck.hpp"

#include <algorithm>
#include <cmath>

namespace aerobreak {
namespace {

// 2 x - 2 e - e^2 with e = 1 - exp(-x): (2/3) x^3 - x^4 / 2 + (7/30) x^5 - ... for small x, where
// the closed form cancels.
double position_variance_factor(double x, double e) {
  if (x < 1e-2) return x * x * x * (2.0 / 3.0 - x * (0.5 - x * 7.0 / 30.0));
  return 2.0 * x - 2.0 * e - e * e;
}

}  // namespace

OrnsteinUhlenbeckStep ornstein_uhlenbeck_step(double mass, double drag, double temperature, double dt) {
  const double gamma = drag / mass;
  const double sigma2 = temperature / mass;
  const double x = gamma * dt;
  const double e = -std::expm1(-x);
  OrnsteinUhlenbeckStep s;
  s.velocity_decay = std::exp(-x);
  s.drift_per_velocity = e / gamma;
  const double velocity_variance = sigma2 * e * (2.0 - e);
  s.velocity_spread = std::sqrt(velocity_variance);
  const double covariance = sigma2 * e * e / gamma;
  const double position_variance = sigma2 / (gamma * gamma) * position_variance_factor(x, e);
  s.correlated_spread = velocity_variance > 0.0 ? covariance / s.velocity_spread : 0.0;
  s.independent_spread = std::sqrt(std::max(0.0, position_variance - s.correlated_spread * s.correlated_spread));
  return s;
}

double ornstein_uhlenbeck_mean_square_displacement(double mass, double drag, double temperature, double t) {
  const double gamma = drag / mass;
  return 2.0 * temperature / drag * (t + std::expm1(-gamma * t) / gamma);
}

}  // namespace aerobreak
