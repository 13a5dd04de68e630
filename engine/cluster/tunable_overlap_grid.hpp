#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "engine/core/vec3.hpp"

namespace aerobreak {

// Spheres hashed into cubic cells, for "does this new sphere overlap any of them" and "which
// spheres lie near this point" queries in O(1) each. With the cell edge at least twice the largest
// radius, a sphere of radius r <= r_max can only overlap spheres whose centres lie within
// r + r_max <= one edge, so at most 2 x 2 x 2 cells are looked up. Occupied cells are found through
// an open-addressing hash table and chained through the spheres, so memory is O(N) however sparse
// the aggregate; spheres can be added one at a time. A bounding sphere about the origin rejects far
// queries first.
class TunableOverlapGrid {
 public:
  // The cell edge must be at least twice the largest radius inserted or queried. Throws
  // std::invalid_argument for a non-positive or non-finite cell edge.
  explicit TunableOverlapGrid(double cell_edge);

  // Adds sphere number size(); throws std::invalid_argument for a non-positive radius.
  void insert(const Vec3& centre, double radius);
  std::size_t size() const { return position_.size(); }
  const Vec3& position(std::size_t i) const { return position_[i]; }
  double radius(std::size_t i) const { return radius_[i]; }

  // True when a sphere at `centre` of radius `radius` has its centre closer than
  // (1 - relative_tolerance)(radius + r_i) to some sphere i.
  bool overlaps(const Vec3& centre, double radius, double relative_tolerance) const;

  // Calls visit(i, centre_i, radius_i) for every sphere i whose centre lies within `reach` of
  // `point` (and possibly a few farther ones: the cells covering the reach are visited whole).
  template <class Visit>
  void for_each_near(const Vec3& point, double reach, Visit&& visit) const {
    for (std::int64_t ix = cell_of(point.x - reach); ix <= cell_of(point.x + reach); ++ix) {
      for (std::int64_t iy = cell_of(point.y - reach); iy <= cell_of(point.y + reach); ++iy) {
        for (std::int64_t iz = cell_of(point.z - reach); iz <= cell_of(point.z + reach); ++iz) {
          const Slot* s = find(pack(ix, iy, iz));
          if (!s) continue;
          for (std::uint32_t i = s->head; i != none; i = next_[i]) {
            visit(i, position_[i], radius_[i]);
          }
        }
      }
    }
  }

 private:
  static constexpr std::uint32_t none = 0xFFFFFFFFu;
  struct Slot {
    std::uint64_t key = 0;
    std::uint32_t head = none;  // none: empty slot
  };

  static std::uint64_t pack(std::int64_t ix, std::int64_t iy, std::int64_t iz);
  std::int64_t cell_of(double coordinate) const;
  const Slot* find(std::uint64_t key) const;
  Slot& slot_for(std::uint64_t key);
  void grow_table();

  double inverse_edge_ = 0.0;
  double bounding_radius_ = 0.0;
  std::vector<Vec3> position_;
  std::vector<double> radius_;
  std::vector<std::uint32_t> next_;  // the next sphere in the same cell, or none
  std::vector<Slot> table_;
  std::size_t occupied_ = 0;
};

}  // namespace aerobreak
