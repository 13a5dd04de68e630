#pragma once
#include "engine/core/material.hpp"

namespace aerobreak {

// Normal stiffness of eq 7, k_n = E d / (3 (1 - nu^2)), for identical spheres of diameter d.
double normal_stiffness(const Material& material, double diameter);

// Adhesion-to-kinetic energy ratio of eq 19 for one primary: lambda = 2 F_c delta_c / (m v0^2),
// with F_c = 3 pi gamma d / 4 and delta_c = 2 a0^2 / (d 6^(1/3)) (eqs 3-5).
double adhesion_energy_ratio(const Material& material, double diameter, double impact_speed);

// The report's reduced units (section 3.1) with gravity off: length d = 1 (primary diameter),
// mass m = 1 (primary mass, so density 6/pi), time tau = sqrt(m / k_n) (so k_n = 1, eq 7).
// A reduced material is fixed by gamma/k_n and nu.
Material reduced_material(double gamma_over_kn, double poisson_ratio);

// Physical mode (docs/MODEL.md 1.2): a real material and impact speed, run with the stiffness
// softened by s (k_n' = s k_n), gamma' = s gamma (gamma/k_n kept) and v' = sqrt(s) v (eq 19's
// lambda kept). In the reduced units above the softened problem is the same dimensionless
// problem for every s: s only relabels time, t_physical = t_reduced * tau, whereas the softened
// simulation's own clock reads t_reduced * tau / sqrt(s). Both are reported.
struct PhysicalScaling {
  Material material;       // physical (SI) material
  double diameter = 0.0;   // m
  double softening = 1.0;  // s, 0 < s <= 1

  double mass() const;         // kg
  double stiffness() const;    // k_n (eq 7), N/m
  double time_unit() const;    // tau = sqrt(m / k_n), s
  double speed_unit() const;   // d / tau, m/s
  double energy_unit() const;  // k_n d^2, J
  Material reduced() const;    // the reduced material of the same gamma/k_n and nu
  double reduced_speed(double speed) const { return speed / speed_unit(); }
  double physical_speed(double reduced) const { return reduced * speed_unit(); }
  double physical_time(double reduced) const { return reduced * time_unit(); }
  double softened_time(double reduced) const;  // on the softened simulation's clock
  void validate() const;
};

}  // namespace aerobreak
