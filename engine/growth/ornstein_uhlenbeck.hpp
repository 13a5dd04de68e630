#pragma once

namespace aerobreak {

// Exact update over a step dt of one Cartesian component (x, v) of a free body of mass M in a bath
// of drag Z and temperature kT, M dv = -Z v dt + sqrt(2 Z kT) dW: the Ornstein-Uhlenbeck process
// and its integral (Uhlenbeck & Ornstein 1930; Chandrasekhar 1943, Rev. Mod. Phys. 15 1, eqs
// 171-177; the sampling as in Gillespie 1996, Phys. Rev. E 54 2084, eqs 2.1-2.6). With
// gamma = Z / M, mu = exp(-gamma dt), e = 1 - mu and sigma^2 = kT / M:
//   v' = mu v + s_v g1,                     s_v^2 = sigma^2 e (2 - e)          (= sigma^2 (1 - mu^2))
//   x' = x + v e / gamma + c / s_v g1 + s_r g2,
//        c = sigma^2 e^2 / gamma   (covariance of x' and v'),
//        s_x^2 = sigma^2 / gamma^2 (2 gamma dt - 2 e - e^2)                 (= ... - 3 + 4 mu - mu^2)
//        s_r^2 = s_x^2 - c^2 / s_v^2,
// g1, g2 independent standard normals. Exact for any dt: the velocity autocorrelation
// sigma^2 exp(-gamma t) and the mean square displacement 2 D (t - (1 - exp(-gamma t)) / gamma),
// D = kT / Z, are those of the Langevin equation itself, whatever the step.
struct OrnsteinUhlenbeckStep {
  double velocity_decay = 1.0;      // mu
  double velocity_spread = 0.0;     // s_v
  double drift_per_velocity = 0.0;  // e / gamma
  double correlated_spread = 0.0;   // c / s_v
  double independent_spread = 0.0;  // s_r

  // Applies the step to (x, v) with the two standard normals g1, g2.
  void advance(double& x, double& v, double g1, double g2) const {
    x += drift_per_velocity * v + correlated_spread * g1 + independent_spread * g2;
    v = velocity_decay * v + velocity_spread * g1;
  }
};

OrnsteinUhlenbeckStep ornstein_uhlenbeck_step(double mass, double drag, double temperature, double dt);

// Mean square displacement per axis after a time t from a thermal start (Ornstein & Uhlenbeck):
// 2 D (t - (1 - exp(-gamma t)) / gamma); <= min(2 D t, (kT / M) t^2).
double ornstein_uhlenbeck_mean_square_displacement(double mass, double drag, double temperature, double t);

}  // namespace aerobreak
