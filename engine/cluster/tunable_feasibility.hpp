#pragma once
#include <optional>
#include <string>

#include "engine/cluster/tunable_scaling_law.hpp"

namespace aerobreak {

// The geometric window of the smallest aggregate the law applies to. Three touching primaries of
// radius a have Rg between that of the equilateral triangle (centres 2a apart: Rg^2 = 4a^2/3) and
// that of the straight chain (Rg^2 = 8a^2/3), plus (3/5) a^2 for solid spheres. The law asks for
// Rg = a (3 / kf)^(1 / Df); it is accepted when within a relative `tolerance` of the window, i.e.
//   3 / ((1 + tolerance) Rg_chain / a)^Df <= kf <= 3 / ((1 - tolerance) Rg_triangle / a)^Df.
// Outside, every particle-cluster aggregate would start far off the law: too open below the lower
// bound (the law wants three primaries wider than a straight chain), too compact above the upper.
struct PrefactorWindow {
  double lowest = 0.0;
  double highest = 0.0;
};
PrefactorWindow three_primary_prefactor_window(double fractal_dimension, GyrationConvention convention,
                                               double tolerance);

// Why (Df, kf) falls outside the window, or nothing when it is inside.
std::optional<std::string> three_primary_shortfall(const FractalLaw& law, double tolerance);

}  // namespace aerobreak
