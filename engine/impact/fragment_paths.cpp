#include "engine/impact/fragment_paths.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace aerobreak {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// A path over a stretch of time that holds no stop: centre p + q t, radius r + k t.
struct Piece {
  Vec3 p, q;
  double r = 0.0, k = 0.0;
};

Piece piece_of(const FragmentPath& a, double t) {
  if (t < a.stop) return {a.centre, a.velocity, a.radius, 0.0};
  // After the stop, with t counted from now: centre c + v stop + after (t - stop), radius
  // R + spread (t - stop).
  const Vec3 at = a.centre + a.stop * a.velocity;
  return {at - a.stop * a.after, a.after, a.radius - a.spread * a.stop, a.spread};
}

// The least of g(t) = |p + q t| - k t over [t0, t1] (t1 may be infinite; k >= 0). g is convex (the
// norm of an affine map less a linear one), so its least value is at its stationary point or an
// end: g' = (p + q t).q / |p + q t| - k vanishes where the angle between p + q t and q has cosine
// c = k / |q|, i.e. where the part of p + q t along q is c |p_perp| / (1 - c^2)^(1/2).
double least_gap(const Vec3& p, const Vec3& q, double k, double t0, double t1) {
  const auto g = [&](double t) { return norm(p + t * q) - k * t; };
  const double speed = norm(q);
  if (std::isinf(t1) && k > speed) return -kInfinity;  // the ball outgrows any course
  if (speed == 0.0) return std::isinf(t1) ? (k > 0.0 ? -kInfinity : g(t0)) : std::min(g(t0), g(t1));
  const Vec3 along = q / speed;
  const double p_along = dot(p, along);
  if (k >= speed) {  // g never rises: its least value is at the end, or its limit
    return std::isinf(t1) ? p_along : g(t1);
  }
  const double c = k / speed;
  const double across = std::sqrt(std::max(norm2(p) - p_along * p_along, 0.0));
  const double stationary = (c * across / std::sqrt(1.0 - c * c) - p_along) / speed;
  return g(std::clamp(stationary, t0, t1));
}

}  // namespace

bool paths_can_meet(const FragmentPath& a, const FragmentPath& b) {
  std::array<double, 4> times{0.0, std::max(a.stop, 0.0), std::max(b.stop, 0.0), kInfinity};
  std::sort(times.begin(), times.end());
  for (std::size_t s = 0; s + 1 < times.size(); ++s) {
    const double t0 = times[s], t1 = times[s + 1];
    if (!(t1 > t0) || std::isinf(t0)) continue;
    const Piece x = piece_of(a, t0), y = piece_of(b, t0);
    const double reach = x.r + y.r;
    if (least_gap(y.p - x.p, y.q - x.q, x.k + y.k, t0, t1) - reach <= 0.0) return true;
  }
  return false;
}

}  // namespace aerobreak
