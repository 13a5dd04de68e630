#pragma once
#include "engine/core/vec3.hpp"

namespace aerobreak {

// Turns a spring stretch kept from the previous step into the current tangent plane (normal n)
// without changing its length, so that a rigid rotation of the pair stores no energy.
[[gnu::always_inline]] inline Vec3 rotate_into_plane(const Vec3& stretch, const Vec3& n) {
  const Vec3 projected = stretch - dot(stretch, n) * n;
  const double before = norm2(stretch);
  const double after = norm2(projected);
  // A select, not a branch: the pair loop evaluates several contacts per vector instruction.
  return projected * (after > 0.0 ? std::sqrt(before / after) : 0.0);
}

// Energy a capped spring dissipates in one step: the work its force does along the stretch
// increment (trapezoidal in the force, as velocity Verlet applies it) minus the change of its
// stored energy, both at the stiffness k of this step:
// D = k/2 [(s_old + s_new).increment + |s_old|^2 - |s_new|^2]. Zero while the spring stays
// elastic (s_new = s_old + increment); k |s| |increment| while it slides at its limit.
[[gnu::always_inline]] inline double slip_dissipation(double stiffness, const Vec3& before, const Vec3& increment,
                                                      const Vec3& after) {
  return 0.5 * stiffness * (dot(before + after, increment) + norm2(before) - norm2(after));
}

}  // namespace aerobreak
