// Exact Ornstein-Uhlenbeck step of a free body in a Langevin bath: its moments against the closed
// forms (Chandrasekhar 1943), and sampled motion that does not depend on the step size.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "engine/cluster/random_stream.hpp"
#include "engine/growth/ornstein_uhlenbeck.hpp"

using namespace aerobreak;

TEST_CASE("the step's variances and covariance are those of the Ornstein-Uhlenbeck process") {
  const double mass = 2.0, drag = 0.5, kt = 0.3;
  const double gamma = drag / mass, sigma2 = kt / mass;
  for (double x : {0.1, 1.0, 50.0}) {
    const double dt = x / gamma, mu = std::exp(-x);
    const OrnsteinUhlenbeckStep s = ornstein_uhlenbeck_step(mass, drag, kt, dt);
    INFO("gamma dt = " << x);
    CHECK(s.velocity_decay == Approx(mu).epsilon(1e-12));
    CHECK(s.velocity_spread * s.velocity_spread == Approx(sigma2 * (1.0 - mu * mu)).epsilon(1e-12));
    CHECK(s.correlated_spread * s.velocity_spread == Approx(sigma2 * (1.0 - mu) * (1.0 - mu) / gamma).epsilon(1e-12));
    const double position_variance =
        s.correlated_spread * s.correlated_spread + s.independent_spread * s.independent_spread;
    CHECK(position_variance == Approx(sigma2 / (gamma * gamma) * (2.0 * x - 3.0 + 4.0 * mu - mu * mu)).epsilon(1e-9));
  }
  // Short steps: the series (2/3) x^3 - x^4 / 2 + ... instead of the cancelling closed form;
  // ballistic limit (kT / M) dt^2 for the spread of x' and v' together.
  const double x = 1e-4, dt = x / gamma;
  const OrnsteinUhlenbeckStep s = ornstein_uhlenbeck_step(mass, drag, kt, dt);
  const double position_variance =
      s.correlated_spread * s.correlated_spread + s.independent_spread * s.independent_spread;
  CHECK(position_variance ==
        Approx(sigma2 / (gamma * gamma) * (2.0 / 3.0) * x * x * x * (1.0 - 0.75 * x)).epsilon(1e-7));
  CHECK(s.drift_per_velocity == Approx(dt).epsilon(1e-4));
}

TEST_CASE("sampled displacements and velocity memory match the Langevin equation at any step") {
  // 20000 bodies from a thermal start, taken to t = 3 M / Z in one step or in 64: mean square
  // displacement 2 D (t - (1 - exp(-gamma t)) / gamma) and <v(0) v(t)> = (kT / M) exp(-gamma t),
  // each within 4 standard errors (for a Gaussian, the standard error of the mean of x^2 is
  // <x^2> sqrt(2 / K); of v(0) v(t), below (kT / M) / sqrt(K)).
  const double mass = 1.0, drag = 0.25, kt = 0.02, t = 3.0 * mass / drag;
  const int bodies = 20000;
  const double expected_msd = ornstein_uhlenbeck_mean_square_displacement(mass, drag, kt, t);
  const double expected_memory = kt / mass * std::exp(-drag / mass * t);
  CHECK(expected_msd == Approx(2.0 * kt / drag * (t - (1.0 - std::exp(-3.0)) * mass / drag)));
  for (int steps : {1, 64}) {
    RandomStream random(7);
    const OrnsteinUhlenbeckStep s = ornstein_uhlenbeck_step(mass, drag, kt, t / steps);
    double msd = 0.0, memory = 0.0;
    for (int b = 0; b < bodies; ++b) {
      double x = 0.0, v = std::sqrt(kt / mass) * random.standard_normal();
      const double v0 = v;
      for (int k = 0; k < steps; ++k) {
        const double g1 = random.standard_normal();
        s.advance(x, v, g1, random.standard_normal());
      }
      msd += x * x / bodies;
      memory += v0 * v / bodies;
    }
    INFO(steps << " steps: MSD " << msd << " against " << expected_msd << ", <v(0) v(t)> " << memory << " against "
               << expected_memory);
    CHECK(std::abs(msd - expected_msd) < 4.0 * expected_msd * std::sqrt(2.0 / bodies));
    CHECK(std::abs(memory - expected_memory) < 4.0 * kt / mass / std::sqrt(bodies));
  }
}
