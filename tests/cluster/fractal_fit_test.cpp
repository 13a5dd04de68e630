#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "engine/cluster/fractal_scaling_fit.hpp"
#include "engine/cluster/line_fit.hpp"

using namespace aerobreak;

TEST_CASE("Line fit recovers an exact line with zero standard error") {
  const std::vector<double> x{0.0, 1.0, 2.0, 3.0};
  const std::vector<double> y{1.0, 3.0, 5.0, 7.0};
  const LineFit fit = fit_line(x, y);
  CHECK(fit.slope == Approx(2.0).epsilon(1e-14));
  CHECK(fit.intercept == Approx(1.0).epsilon(1e-14));
  CHECK(fit.slope_standard_error == Approx(0.0).margin(1e-14));
  CHECK(fit.point_count == 4);
}

TEST_CASE("Line fit standard errors match the textbook values") {
  // Residuals +1, -2, +1 about y = x: s^2 = 6 / 1, Sxx = 2, SE(slope) = sqrt(3), and
  // SE(intercept) = sqrt(6 (1/3 + 1/2)) = sqrt(5).
  const std::vector<double> x{0.0, 1.0, 2.0};
  const std::vector<double> y{1.0, -1.0, 3.0};
  const LineFit fit = fit_line(x, y);
  CHECK(fit.slope == Approx(1.0));
  CHECK(fit.intercept == Approx(0.0).margin(1e-14));
  CHECK(fit.slope_standard_error == Approx(std::sqrt(3.0)));
  CHECK(fit.intercept_standard_error == Approx(std::sqrt(5.0)));
}

TEST_CASE("Fractal scaling fit recovers D_f and k_f of an exact power law") {
  const double df = 1.78;
  const double kf = 1.4;
  const double a = 0.5;
  std::vector<SizeRadiusSample> samples;
  for (double n : {16.0, 64.0, 256.0, 1024.0}) {
    samples.push_back({n, a * std::pow(n / kf, 1.0 / df)});
  }
  const FractalScalingFit fit = fit_fractal_scaling(samples, a);
  CHECK(fit.fractal_dimension == Approx(df).epsilon(1e-12));
  CHECK(fit.prefactor == Approx(kf).epsilon(1e-12));
  CHECK(fit.fractal_dimension_standard_error < 1e-10);
  CHECK(fit.sample_count == 4);
  CHECK(fit.min_primary_count == 16.0);
  CHECK(fit.max_primary_count == 1024.0);
  CHECK(fit.min_normalised_radius == Approx(std::pow(16.0 / kf, 1.0 / df)));
  CHECK(fit.max_normalised_radius == Approx(std::pow(1024.0 / kf, 1.0 / df)));
}

TEST_CASE("Fits reject unusable input") {
  const std::vector<SizeRadiusSample> two{{10.0, 2.0}, {20.0, 3.0}};
  CHECK_THROWS_AS(fit_fractal_scaling(two, 0.5), std::invalid_argument);
  const std::vector<SizeRadiusSample> three{{10.0, 2.0}, {20.0, 3.0}, {40.0, 4.5}};
  CHECK_THROWS_AS(fit_fractal_scaling(three, 0.0), std::invalid_argument);
  const std::vector<SizeRadiusSample> bad_rg{{10.0, 2.0}, {20.0, -3.0}, {40.0, 4.5}};
  CHECK_THROWS_AS(fit_fractal_scaling(bad_rg, 0.5), std::invalid_argument);
  const std::vector<SizeRadiusSample> one_n{{10.0, 2.0}, {10.0, 2.5}, {10.0, 3.0}};
  CHECK_THROWS_AS(fit_fractal_scaling(one_n, 0.5), std::invalid_argument);
  const std::vector<SizeRadiusSample> flat{{10.0, 2.0}, {20.0, 2.0}, {40.0, 2.0}};
  CHECK_THROWS_AS(fit_fractal_scaling(flat, 0.5), std::invalid_argument);
  CHECK_THROWS_AS(fit_line(std::vector<double>{1.0, 2.0}, std::vector<double>{1.0, 2.0}), std::invalid_argument);
}
