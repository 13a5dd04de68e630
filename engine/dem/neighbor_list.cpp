#include "engine/dem/neighbor_list.hpp"

#include <algorithm>

namespace aerobreak {

VerletNeighborList::VerletNeighborList(std::unique_ptr<NeighborSearch> search, double margin, double skin)
    : search_(std::move(search)), margin_(margin), skin_(skin) {}

void VerletNeighborList::rebuild(const Particles& particles, const ContactPool& pool, std::vector<std::int32_t>& lost) {
  search_->find_pairs(particles.position, particles.radius, margin_ + skin_, pairs_);
  built_at_ = particles.position;
  ++builds_;
  // Hand every live particle-particle contact its slot in the new list (rows are sorted by j).
  for (std::size_t slot = 0; slot < pool.capacity(); ++slot) {
    if (!pool.live(slot)) continue;
    const std::uint32_t i = pool.i(slot), j = pool.j(slot);
    const auto first = pairs_.neighbor.begin() + pairs_.row_start[i];
    const auto last = pairs_.neighbor.begin() + pairs_.row_start[i + 1];
    const auto at = std::lower_bound(first, last, j);
    if (at != last && *at == j)
      pairs_.contact[at - pairs_.neighbor.begin()] = static_cast<std::int32_t>(slot);
    else
      lost.push_back(static_cast<std::int32_t>(slot));
  }
}

}  // namespace aerobreak
