#pragma once
#include <cstdint>

namespace aerobreak {

// Seed of cluster `index` (0, 1, ...) of a generation with base seed `base`: output index + 1 of a
// SplitMix64 generator seeded with `base` (Steele, Lea & Flood 2014), so that neighbouring base
// seeds do not share clusters.
inline std::uint64_t derived_seed(std::uint64_t base, std::uint64_t index) {
  std::uint64_t z = base + (index + 1) * 0x9E3779B97F4A7C15ULL;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

}  // namespace aerobreak
