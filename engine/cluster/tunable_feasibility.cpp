#include "engine/cluster/tunable_feasibility.hpp"

#include <cmath>
#include <sstream>

namespace aerobreak {
namespace {

struct ThreePrimaryGyration {
  double triangle = 0.0;  // in units of the primary radius
  double chain = 0.0;
};

ThreePrimaryGyration three_primary_gyration(GyrationConvention convention) {
  const double own = primary_gyration_squared(1.0, convention);
  return {std::sqrt(4.0 / 3.0 + own), std::sqrt(8.0 / 3.0 + own)};
}

}  // namespace

PrefactorWindow three_primary_prefactor_window(double fractal_dimension, GyrationConvention convention,
                                               double tolerance) {
  const ThreePrimaryGyration g = three_primary_gyration(convention);
  return {3.0 / std::pow((1.0 + tolerance) * g.chain, fractal_dimension),
          3.0 / std::pow((1.0 - tolerance) * g.triangle, fractal_dimension)};
}

std::optional<std::string> three_primary_shortfall(const FractalLaw& law, double tolerance) {
  const PrefactorWindow window = three_primary_prefactor_window(law.fractal_dimension, law.convention, tolerance);
  if (law.prefactor >= window.lowest && law.prefactor <= window.highest) return std::nullopt;
  const ThreePrimaryGyration g = three_primary_gyration(law.convention);
  std::ostringstream out;
  out.precision(4);
  out << "particle-cluster stage, three primaries: the law asks for Rg = " << law.gyration_radius(3.0, 1.0)
      << " a, but three touching primaries of radius a have Rg "
      << "from " << g.triangle << " a (triangle) to " << g.chain << " a (straight chain); "
      << (law.prefactor < window.lowest ? "too open" : "too compact") << ": at Df = " << law.fractal_dimension
      << " kf must lie in [" << window.lowest << ", " << window.highest << "] (the window widened by "
      << 100.0 * tolerance << "%)";
  return out.str();
}

}  // namespace aerobreak
