#pragma once
// The sticking speed of one primary hitting an adhesive wall of its own material head-on, in
// physical units, found with the impact pipeline users run (a physical case of one primary,
// `run_impact`, the automatic time step, classification by what leaves the wall): the speed below
// which the sphere stays on the wall. Undamped and frictionless, so that the only loss is the JKR
// loop (report eqs 1-5) and the speed follows from dimensional analysis (docs/STUDIES.md 3).
#include <vector>

namespace aerobreak::validation {

// SI material of the primaries and the wall.
struct MaterialSI {
  double youngs_modulus = 25e9;  // Pa
  double poisson_ratio = 0.3;
  double density = 1725.0;       // kg/m^3
  double surface_energy = 0.05;  // J/m^2
};

// True when a primary of `diameter` (m) hitting the wall at `speed` (m/s) sticks.
bool monomer_sticks(const MaterialSI& material, double diameter, double speed);

// The sticking speed (m/s) by bisection on `monomer_sticks` to a relative width `tolerance`.
double monomer_sticking_speed(const MaterialSI& material, double diameter, double tolerance = 1e-4);

// The closed form for the same contact: v = (2 U_b / m)^(1/2), U_b = 0.9355 F_c delta_c the energy
// of one JKR loop with displacement-controlled release (docs/VALIDATION.md 2), with the wall's
// R* = d/2, E* = E / (2 (1 - nu^2)), w = 2 gamma (docs/MODEL.md 2).
double exact_monomer_sticking_speed(const MaterialSI& material, double diameter);

// Least-squares slope of ln y on ln x.
double log_log_slope(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace aerobreak::validation
