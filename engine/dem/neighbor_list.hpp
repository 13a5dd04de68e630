#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "engine/core/particles.hpp"
#include "engine/dem/contact_pool.hpp"
#include "engine/neighbor/neighbor_search.hpp"

namespace aerobreak {

// Verlet list with a skin: pairs within R_i + R_j + margin + skin are listed, and the list is
// rebuilt only when some particle has moved more than skin/2 since the last build, so no pair
// can come within `margin` unlisted. Live contacts keep their pool slots across rebuilds. `pool`
// holds the particle-particle contacts only.
class VerletNeighborList {
 public:
  VerletNeighborList(std::unique_ptr<NeighborSearch> search, double margin, double skin);

  // Positions at the last build, and the squared displacement from them past which the list is
  // stale (some particle has moved more than skin/2): the caller checks while it moves them.
  const std::vector<Vec3>& built_at() const { return built_at_; }
  double displacement_limit2() const { return 0.25 * skin_ * skin_; }
  // Lists the pairs anew; appends to `lost` the contacts whose pair is no longer listed (none
  // unless the particles moved further than the skin allows), for the caller to close.
  void rebuild(const Particles& particles, const ContactPool& pool, std::vector<std::int32_t>& lost);

  PairList& pairs() { return pairs_; }
  const PairList& pairs() const { return pairs_; }
  std::uint64_t builds() const { return builds_; }
  double skin() const { return skin_; }

 private:
  std::unique_ptr<NeighborSearch> search_;
  double margin_;
  double skin_;
  PairList pairs_;
  std::vector<Vec3> built_at_;
  std::uint64_t builds_ = 0;
};

}  // namespace aerobreak
