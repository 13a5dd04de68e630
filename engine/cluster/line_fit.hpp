#pragma once
#include <cstddef>
#include <span>

namespace aerobreak {

// Ordinary least-squares straight line y = intercept + slope * x, with the standard errors of both
// coefficients from the residual variance s^2 = sum(residual^2) / (n - 2).
struct LineFit {
  double slope = 0.0;
  double intercept = 0.0;
  double slope_standard_error = 0.0;
  double intercept_standard_error = 0.0;
  std::size_t point_count = 0;
};

// Throws std::invalid_argument if x and y differ in length, there are fewer than 3 points (no
// residual degree of freedom), or all x are equal.
LineFit fit_line(std::span<const double> x, std::span<const double> y);

}  // namespace aerobreak
