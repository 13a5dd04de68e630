// The monomer-wall sticking speed against the primary diameter in physical units, through the
// impact pipeline users run (a physical case of one primary, automatic time step, classification
// by what leaves the wall), undamped and frictionless. Dimensional analysis of the JKR loss
// (gamma, E*, rho and d are the only inputs; docs/STUDIES.md 3) gives v_stick ~ d^(-5/6).
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "tests/validation/monomer_sticking.hpp"

using namespace aerobreak::validation;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

TEST_CASE("the monomer-wall sticking speed falls as d^(-5/6) from 10 nm to 1 um at the automatic step") {
  // Ammonium-nitrate-like primaries (the default study's material, docs/STUDIES.md 1). Each speed
  // is found by bisection to 1e-4 and must be within 1 % of the closed form, the accuracy the
  // automatic step guarantees for the sticking speed (tests/engine/jkr_restitution_test.cpp); two
  // such errors over two decades move the slope by at most 2 x 0.01 / ln(100) = 0.0043, hence
  // 0.005. Measured: ratios 0.99996-1.00021, slope -0.83332 (build/tests/validation/sticking_speed_scan).
  const MaterialSI material;
  const std::vector<double> diameters = {10e-9, 100e-9, 1000e-9};
  std::vector<double> speeds;
  for (double d : diameters) {
    const double v = monomer_sticking_speed(material, d);
    INFO("d = " << d << " m: v_stick = " << v << " m/s");
    CHECK_THAT(v, WithinRel(exact_monomer_sticking_speed(material, d), 0.01));
    speeds.push_back(v);
  }
  CHECK_THAT(log_log_slope(diameters, speeds), WithinAbs(-5.0 / 6.0, 0.005));
}

TEST_CASE("the closed-form monomer sticking speed scales as gamma^(5/6) rho^(-1/2) E*^(-1/3) d^(-5/6)") {
  // Independent of the pipeline: doubling each input multiplies the speed by 2 to its exponent
  // (the Chokshi / Dominik & Tielens form, v ~ (gamma/R*)^(5/6) rho^(-1/2) E*^(-1/3)).
  const MaterialSI base;
  const double v = exact_monomer_sticking_speed(base, 20e-9);
  MaterialSI changed = base;
  changed.surface_energy *= 2.0;
  CHECK_THAT(exact_monomer_sticking_speed(changed, 20e-9) / v, WithinRel(std::pow(2.0, 5.0 / 6.0), 1e-12));
  changed = base;
  changed.density *= 2.0;
  CHECK_THAT(exact_monomer_sticking_speed(changed, 20e-9) / v, WithinRel(std::pow(2.0, -0.5), 1e-12));
  changed = base;
  changed.youngs_modulus *= 2.0;
  CHECK_THAT(exact_monomer_sticking_speed(changed, 20e-9) / v, WithinRel(std::pow(2.0, -1.0 / 3.0), 1e-12));
  CHECK_THAT(exact_monomer_sticking_speed(base, 40e-9) / v, WithinRel(std::pow(2.0, -5.0 / 6.0), 1e-12));
}
