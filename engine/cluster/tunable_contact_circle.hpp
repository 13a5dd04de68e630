#pragma once
#include <optional>

#include "engine/cluster/tunable_free_arcs.hpp"
#include "engine/core/vec3.hpp"

namespace aerobreak {

// The circle of points at distance gamma from a centre of mass that also lie at distance `reach`
// (= r_i + r_new) from a primary: where the sphere of radius gamma about the centre meets the
// sphere of radius `reach` about the primary (FracVAL appendix A). A monomer centred anywhere on it
// touches the primary and sits at distance gamma from the centre.
struct ContactCircle {
  Vec3 centre;
  Vec3 u, v;  // orthonormal, spanning the circle's plane
  double radius = 0.0;

  Vec3 at(double angle) const;
};

// Empty when the spheres do not meet or the primary sits at the centre.
std::optional<ContactCircle> contact_circle(const Vec3& centre, const Vec3& primary, double reach, double gamma);

// The arc of the circle on which a monomer would come closer than `contact` to the centre of a
// sphere at x (contact = (1 - tolerance)(r_new + r_x)); empty when it nowhere does.
std::optional<BlockedArc> blocked_arc(const ContactCircle& circle, const Vec3& x, double contact);

}  // namespace aerobreak
