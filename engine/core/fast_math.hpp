#pragma once
#include <bit>
#include <cmath>
#include <cstdint>

namespace aerobreak {

// Cube root of a positive, finite, normal double, to within 3 ulp, without a call into libm
// (whose cbrt goes through frexp/ldexp and is not inlined): an exponent-splitting estimate of
// x^(-1/3), four division-free Newton steps r <- r (4 - x r^3) / 3 (quadratic convergence from
// ~3% to below 1e-16), then y = x r^2 with one Newton polish in the forward form. A fixed
// sequence of arithmetic, like any elementary-function implementation: no data-dependent loop.
// x^(-1/3) for positive, finite, normal x: the division-free part of cube_root below.
// The estimate works on the upper 32 bits (sign, exponent, 20 bits of mantissa), so that it is
// 32-bit integer arithmetic, which vector units have: loops over many x vectorise.
[[gnu::always_inline]] inline double inverse_cube_root(double x) {
  const auto high = static_cast<std::uint32_t>(std::bit_cast<std::uint64_t>(x) >> 32);
  double r = std::bit_cast<double>(static_cast<std::uint64_t>(0x553ef0ffu - high / 3) << 32);
  r = r * (4.0 - x * r * r * r) * (1.0 / 3.0);
  r = r * (4.0 - x * r * r * r) * (1.0 / 3.0);
  r = r * (4.0 - x * r * r * r) * (1.0 / 3.0);
  r = r * (4.0 - x * r * r * r) * (1.0 / 3.0);
  return r;
}

inline double cube_root(double x) {
  const double r = inverse_cube_root(x);
  const double y = x * r * r;
  return y - (y * y * y - x) / (3.0 * y * y);
}

// max(x, 0) as arithmetic: exact for every finite x (x + |x| is 2x or 0). Neither std::max (its
// reference arguments) nor a select feeding a square root (the compiler turns it into a branch
// around the root) lets a loop over contacts vectorise.
[[gnu::always_inline]] inline double positive_part(double x) { return 0.5 * (x + std::fabs(x)); }

}  // namespace aerobreak
