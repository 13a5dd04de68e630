#include "engine/cluster/tunable_overlap_grid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace aerobreak {
namespace {

// SplitMix64's finaliser (Steele, Lea & Flood 2014): spreads neighbouring keys over the table.
std::uint64_t mix(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

}  // namespace

TunableOverlapGrid::TunableOverlapGrid(double cell_edge) : table_(16) {
  if (!(cell_edge > 0.0) || !std::isfinite(cell_edge)) {
    throw std::invalid_argument("TunableOverlapGrid: cell_edge must be positive and finite");
  }
  inverse_edge_ = 1.0 / cell_edge;
}

// Three signed 21-bit cell indices packed into one key; aggregates span far fewer than 2^20 cells.
std::uint64_t TunableOverlapGrid::pack(std::int64_t ix, std::int64_t iy, std::int64_t iz) {
  constexpr std::uint64_t bits = (std::uint64_t{1} << 21) - 1;
  return ((static_cast<std::uint64_t>(ix) & bits) << 42) | ((static_cast<std::uint64_t>(iy) & bits) << 21) |
         (static_cast<std::uint64_t>(iz) & bits);
}

std::int64_t TunableOverlapGrid::cell_of(double coordinate) const {
  return static_cast<std::int64_t>(std::floor(coordinate * inverse_edge_));
}

const TunableOverlapGrid::Slot* TunableOverlapGrid::find(std::uint64_t key) const {
  const std::size_t mask = table_.size() - 1;
  for (std::size_t slot = mix(key) & mask;; slot = (slot + 1) & mask) {
    const Slot& s = table_[slot];
    if (s.head == none) return nullptr;
    if (s.key == key) return &s;
  }
}

TunableOverlapGrid::Slot& TunableOverlapGrid::slot_for(std::uint64_t key) {
  const std::size_t mask = table_.size() - 1;
  for (std::size_t slot = mix(key) & mask;; slot = (slot + 1) & mask) {
    Slot& s = table_[slot];
    if (s.head == none) {
      s.key = key;
      ++occupied_;
      return s;
    }
    if (s.key == key) return s;
  }
}

void TunableOverlapGrid::grow_table() {
  std::vector<Slot> old(2 * table_.size());
  old.swap(table_);
  const std::size_t mask = table_.size() - 1;
  for (const Slot& s : old) {
    if (s.head == none) continue;
    std::size_t slot = mix(s.key) & mask;
    while (table_[slot].head != none) slot = (slot + 1) & mask;
    table_[slot] = s;
  }
}

void TunableOverlapGrid::insert(const Vec3& centre, double radius) {
  if (!(radius > 0.0)) throw std::invalid_argument("TunableOverlapGrid: non-positive radius");
  if (2 * (occupied_ + 1) > table_.size()) grow_table();
  const auto index = static_cast<std::uint32_t>(position_.size());
  Slot& s = slot_for(pack(cell_of(centre.x), cell_of(centre.y), cell_of(centre.z)));
  position_.push_back(centre);
  radius_.push_back(radius);
  next_.push_back(s.head);
  s.head = index;
  bounding_radius_ = std::max(bounding_radius_, norm(centre) + radius);
}

bool TunableOverlapGrid::overlaps(const Vec3& centre, double radius, double relative_tolerance) const {
  if (norm(centre) - radius >= bounding_radius_) return false;
  const double keep = 1.0 - relative_tolerance;
  const double reach = radius + 0.5 / inverse_edge_;
  bool found = false;
  for_each_near(centre, reach, [&](std::uint32_t, const Vec3& x, double r) {
    const double contact = keep * (radius + r);
    found = found || norm2(centre - x) < contact * contact;
  });
  return found;
}

}  // namespace aerobreak
