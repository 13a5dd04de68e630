#include "engine/cluster/line_fit.hpp"

#include <cmath>
#include <stdexcept>

namespace aerobreak {

LineFit fit_line(std::span<const double> x, std::span<const double> y) {
  if (x.size() != y.size()) throw std::invalid_argument("fit_line: x and y differ in length");
  const std::size_t n = x.size();
  if (n < 3) throw std::invalid_argument("fit_line: need at least 3 points");

  double x_mean = 0.0;
  double y_mean = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    x_mean += x[i];
    y_mean += y[i];
  }
  x_mean /= static_cast<double>(n);
  y_mean /= static_cast<double>(n);

  double sxx = 0.0;
  double sxy = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    sxx += (x[i] - x_mean) * (x[i] - x_mean);
    sxy += (x[i] - x_mean) * (y[i] - y_mean);
  }
  if (!(sxx > 0.0)) throw std::invalid_argument("fit_line: all x values are equal");

  LineFit fit;
  fit.point_count = n;
  fit.slope = sxy / sxx;
  fit.intercept = y_mean - fit.slope * x_mean;
  double residual2 = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = y[i] - (fit.intercept + fit.slope * x[i]);
    residual2 += r * r;
  }
  const double s2 = residual2 / static_cast<double>(n - 2);
  fit.slope_standard_error = std::sqrt(s2 / sxx);
  fit.intercept_standard_error = std::sqrt(s2 * (1.0 / static_cast<double>(n) + x_mean * x_mean / sxx));
  return fit;
}

}  // namespace aerobreak
