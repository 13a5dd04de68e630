#pragma once
#include <cstddef>
#include <span>

namespace aerobreak {

// One cluster of an ensemble: its primary count N and radius of gyration Rg.
struct SizeRadiusSample {
  double primary_count = 0.0;
  double radius_of_gyration = 0.0;
};

// Ensemble fractal scaling N = k_f (Rg / a)^D_f (report figure 2b; e.g. Sorensen 2011, Aerosol Sci.
// Technol. 45 765), with the range of N and Rg/a the fit saw: outside it the law is extrapolated.
struct FractalScalingFit {
  double fractal_dimension = 0.0;
  double prefactor = 0.0;
  double fractal_dimension_standard_error = 0.0;
  std::size_t sample_count = 0;
  double min_primary_count = 0.0;
  double max_primary_count = 0.0;
  double min_normalised_radius = 0.0;  // min Rg / a
  double max_normalised_radius = 0.0;  // max Rg / a
};

// Least-squares fit of ln N = ln k_f + D_f ln(Rg / a) over all samples (a = mean primary radius),
// done as the regression of ln(Rg / a) on ln N because the scatter is in Rg, not in N; the standard
// error of D_f comes from the regression residuals (delta method). Throws std::invalid_argument for
// fewer than 3 samples, a non-positive N, Rg or primary_radius, samples that all share one N, or Rg
// not growing with N.
FractalScalingFit fit_fractal_scaling(std::span<const SizeRadiusSample> samples, double primary_radius);

}  // namespace aerobreak
