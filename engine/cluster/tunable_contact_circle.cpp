#include "engine/cluster/tunable_contact_circle.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace aerobreak {

Vec3 ContactCircle::at(double angle) const { return centre + radius * (std::cos(angle) * u + std::sin(angle) * v); }

std::optional<ContactCircle> contact_circle(const Vec3& centre, const Vec3& primary, double reach, double gamma) {
  const Vec3 axis = primary - centre;
  const double d = norm(axis);
  if (!(d > 0.0) || d < std::abs(gamma - reach) || d > gamma + reach) return std::nullopt;
  const Vec3 w = axis / d;
  // The plane of the circle lies `along` from the centre towards the primary.
  const double along = (gamma * gamma - reach * reach + d * d) / (2.0 * d);
  const Vec3 helper = std::abs(w.x) < 0.9 ? Vec3{1.0, 0.0, 0.0} : Vec3{0.0, 1.0, 0.0};
  Vec3 u = cross(w, helper);
  u = u / norm(u);
  return ContactCircle{centre + along * w, u, cross(w, u), std::sqrt(std::max(0.0, gamma * gamma - along * along))};
}

// |P(theta) - x|^2 = |q|^2 + rho^2 + 2 rho (A cos theta + B sin theta) with q = circle centre - x,
// A = q.u, B = q.v. It is below contact^2 where cos(theta - phi) < t, with phi = atan2(B, A),
// H = sqrt(A^2 + B^2) and t = (contact^2 - |q|^2 - rho^2) / (2 rho H): the arc of half-width
// pi - acos(t) about phi + pi (all of the circle for t >= 1, none of it for t <= -1).
std::optional<BlockedArc> blocked_arc(const ContactCircle& circle, const Vec3& x, double contact) {
  const Vec3 q = circle.centre - x;
  const double a = dot(q, circle.u);
  const double b = dot(q, circle.v);
  const double c = contact * contact - norm2(q) - circle.radius * circle.radius;
  const double scale = 2.0 * circle.radius * std::sqrt(a * a + b * b);
  if (!(scale > 0.0)) {
    if (c > 0.0) return BlockedArc{0.0, std::numbers::pi};
    return std::nullopt;
  }
  const double t = c / scale;
  if (t <= -1.0) return std::nullopt;
  if (t >= 1.0) return BlockedArc{0.0, std::numbers::pi};
  return BlockedArc{std::atan2(b, a) + std::numbers::pi, std::numbers::pi - std::acos(t)};
}

}  // namespace aerobreak
