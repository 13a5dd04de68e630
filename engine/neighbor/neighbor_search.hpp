#pragma once
#include <vector>

#include "engine/core/vec3.hpp"
#include "engine/neighbor/pair_list.hpp"

namespace aerobreak {

// Finds every pair i < j whose surfaces are closer than `margin`: |x_i - x_j| < R_i + R_j + margin.
// Fills row_start and neighbor of `out` (rows sorted by j); contact is resized and set to -1.
class NeighborSearch {
 public:
  virtual ~NeighborSearch() = default;
  virtual void find_pairs(const std::vector<Vec3>& position, const std::vector<double>& radius, double margin,
                          PairList& out) = 0;
};

// O(N^2) reference: checks every pair. For tests and tiny systems.
class BruteForceSearch final : public NeighborSearch {
 public:
  void find_pairs(const std::vector<Vec3>& position, const std::vector<double>& radius, double margin,
                  PairList& out) override;
};

// Cell list on a hashed grid: cells of edge 2 R_max + margin are mapped into a table of about
// 2N buckets, so memory and time stay O(N) however far the particles spread (a break-up sends
// fragments in all directions; a dense grid over the bounding box would not stay O(N)).
class CellListSearch final : public NeighborSearch {
 public:
  void find_pairs(const std::vector<Vec3>& position, const std::vector<double>& radius, double margin,
                  PairList& out) override;

 private:
  struct Cell {
    std::int64_t x, y, z;
    friend bool operator==(const Cell&, const Cell&) = default;
  };
  std::vector<Cell> cell_of_;
  std::vector<std::uint32_t> bucket_start_;
  std::vector<std::uint32_t> sorted_;
};

}  // namespace aerobreak
