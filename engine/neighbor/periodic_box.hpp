#pragma once
#include <cmath>
#include <cstdint>

#include "engine/core/vec3.hpp"

namespace aerobreak {

// How many box lengths a particle has been shifted back into the box, per axis: its unwrapped
// position is x + (n_x L_x, n_y L_y, n_z L_z).
struct ImageCount {
  std::int64_t x = 0, y = 0, z = 0;
  friend bool operator==(const ImageCount&, const ImageCount&) = default;
};

// A box [0, L_x) x [0, L_y) x [0, L_z), periodic along all three axes. Pairs interact through
// their nearest images (minimum-image convention, Allen & Tildesley 2017, "Computer Simulation of
// Liquids", section 1.6.3), which is unique while every interaction reaches less than half of the
// shortest edge; the neighbour search and the simulation check that.
struct PeriodicBox {
  Vec3 length;

  // Throws std::invalid_argument unless every edge is positive and finite.
  void validate() const;
  double shortest_edge() const;
  // Throws std::invalid_argument unless an interaction of this reach (centre distance) is shorter
  // than half the shortest edge, so that it sees one image of a partner at most.
  void require_single_image(double reach) const;

  // The nearest image of the displacement d: d - L round(d / L) per axis.
  Vec3 minimum_image(const Vec3& d) const;
  // x shifted into [0, L) per axis; the shifts are added to `image`.
  Vec3 wrap(const Vec3& x, ImageCount& image) const;
  // x + n L: the position before any wrapping.
  Vec3 unwrap(const Vec3& x, const ImageCount& image) const;
};

// Separation vectors for the loops that are compiled once for open space and once for a periodic
// box (chosen once per run): OpenSpace passes the plain difference through untouched, so the
// open-space loop carries no trace of periodicity.
struct OpenSpace {
  [[gnu::always_inline]] Vec3 operator()(const Vec3& d) const { return d; }
};

struct PeriodicSpace {
  explicit PeriodicSpace(const PeriodicBox& box)
      : length(box.length), inverse{1.0 / box.length.x, 1.0 / box.length.y, 1.0 / box.length.z} {}

  // Nearest integer by truncation of t + copysign(1/2, t) (one conversion, no library call).
  [[gnu::always_inline]] static double nearest(double t) {
    return static_cast<double>(static_cast<std::int64_t>(t + std::copysign(0.5, t)));
  }
  [[gnu::always_inline]] Vec3 operator()(const Vec3& d) const {
    return {d.x - length.x * nearest(d.x * inverse.x), d.y - length.y * nearest(d.y * inverse.y),
            d.z - length.z * nearest(d.z * inverse.z)};
  }

  Vec3 length;
  Vec3 inverse;
};

}  // namespace aerobreak
