#pragma once
#include <algorithm>

namespace aerobreak {

// Long-range van der Waals attraction between two spheres outside contact, in the Derjaguin
// approximation of Hamaker's sphere-sphere result (Hamaker 1937; Israelachvili, Intermolecular
// and Surface Forces, ch. 13): F = A R* / (6 z^2) at surface gap z, z clamped below at z0 (the
// separation of maximum attraction, report eq 6), cut off at z_cut. A wall is R* = R_i. Inside a
// contact the JKR/DMT adhesion already accounts for the surface attraction, so this law is
// applied only to pairs that are not in contact. The energy is shifted to zero at the cut-off.
struct VanDerWaals {
  double hamaker = 0.0;         // A
  double min_separation = 0.0;  // z0
  double cutoff = 0.0;          // z_cut, gap beyond which the force is zero

  struct Result {
    double attraction = 0.0;  // magnitude of the force pulling the bodies together
    double energy = 0.0;
  };

  Result at_gap(double gap, double reduced_radius) const {
    if (gap >= cutoff) return {};
    const double z = std::max(gap, min_separation);
    const double scale = hamaker * reduced_radius / 6.0;
    Result r;
    r.attraction = scale / (z * z);
    // Below z0 the force is held constant, so the energy continues linearly.
    r.energy = -scale / z + scale / cutoff - r.attraction * (z - gap);
    return r;
  }
};

}  // namespace aerobreak
