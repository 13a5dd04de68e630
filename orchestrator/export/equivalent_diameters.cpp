#include "orchestrator/export/equivalent_diameters.hpp"

#include <cmath>

namespace aerobreak {
namespace {

// Bisection of an increasing function f on [low, high] in ln x for f(x) = target, to double precision.
template <typename F>
double solve_increasing(F f, double target, double low, double high) {
  for (int i = 0; i < 200; ++i) {
    const double middle = std::sqrt(low * high);
    (f(middle) < target ? low : high) = middle;
  }
  return std::sqrt(low * high);
}

}  // namespace

double volume_equivalent_diameter(double primaries) { return std::cbrt(primaries); }

double mobility_equivalent_diameter(double primaries) {
  return std::pow(primaries / kProjectedAreaPrefactor, 1.0 / (2.0 * kProjectedAreaExponent));
}

double slip_correction(double diameter) {
  const double knudsen = 2.0 * kAirMeanFreePath / diameter;
  return 1.0 + knudsen * (1.165 + 0.483 * std::exp(-0.997 / knudsen));
}

double aerodynamic_diameter(double primaries, double primary_diameter, double density) {
  const double d_ve = primary_diameter * volume_equivalent_diameter(primaries);
  const double d_mob = primary_diameter * mobility_equivalent_diameter(primaries);
  // rho_0 d_ae^2 Cc(d_ae) = rho_p d_ve^3 Cc(d_mob) / d_mob; the left side increases with d_ae.
  const double target = density * d_ve * d_ve * d_ve * slip_correction(d_mob) / (d_mob * kUnitDensity);
  return solve_increasing([](double d) { return d * d * slip_correction(d); }, target, 1e-12, 1.0);
}

double primaries_of_diameter(DiameterType type, double diameter, double primary_diameter, double density) {
  switch (type) {
    case DiameterType::volume:
      return diameter * diameter * diameter;
    case DiameterType::mobility:
      return kProjectedAreaPrefactor * std::pow(diameter, 2.0 * kProjectedAreaExponent);
    case DiameterType::aerodynamic:
      break;
  }
  return solve_increasing([&](double n) { return aerodynamic_diameter(n, primary_diameter, density); }, diameter, 1e-6,
                          1e18);
}

}  // namespace aerobreak
