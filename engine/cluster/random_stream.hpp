#pragma once
#include <cstdint>
#include <random>
#include <vector>

#include "engine/cluster/rotation.hpp"
#include "engine/core/vec3.hpp"

namespace aerobreak {

// A seeded random stream whose output is fixed by the seed alone. std::mt19937_64's sequence is
// specified by the C++ standard, but std::uniform_real_distribution, std::normal_distribution etc.
// are implementation-defined, so every distribution here is written out explicitly.
class RandomStream {
 public:
  explicit RandomStream(std::uint64_t seed) : engine_(seed) {}

  // Uniform on [0, 1): the top 53 bits of one 64-bit draw.
  double uniform();
  // Standard normal by the Box-Muller transform (Box & Muller 1958); the sine partner is discarded.
  double standard_normal();
  // Uniform on the unit sphere (Archimedes: z uniform on [-1, 1], azimuth uniform).
  Vec3 unit_vector();
  // Uniform over SO(3): a uniform unit quaternion from three uniforms (Shoemake 1992, Graphics
  // Gems III, "Uniform random rotations").
  Rotation rotation();
  // n primary radii, lognormal: ln d ~ Normal(ln d_g, ln sigma_g); sigma_g = 1 is monodisperse
  // (and draws nothing).
  std::vector<double> lognormal_radii(std::size_t n, double geometric_mean_diameter,
                                      double geometric_standard_deviation);

 private:
  std::mt19937_64 engine_;
};

}  // namespace aerobreak
