#pragma once
#include <optional>
#include <vector>

#include "engine/core/vec3.hpp"
#include "engine/neighbor/pair_list.hpp"
#include "engine/neighbor/periodic_box.hpp"

namespace aerobreak {

// Finds every pair i < j whose surfaces are closer than `margin`: |x_i - x_j| < R_i + R_j + margin.
// Fills row_start and neighbor of `out` (rows sorted by j); contact is resized and set to -1.
// In a periodic box the distance is that of the nearest images (PeriodicBox), and positions may
// lie anywhere (they are wrapped here only to find cells); find_pairs then throws
// std::invalid_argument unless the largest reach 2 R_max + margin is below half the shortest edge,
// so that no pair interacts through two images.
class NeighborSearch {
 public:
  virtual ~NeighborSearch() = default;
  virtual void find_pairs(const std::vector<Vec3>& position, const std::vector<double>& radius, double margin,
                          PairList& out) = 0;
};

// O(N^2) reference: checks every pair. For tests and tiny systems.
class BruteForceSearch final : public NeighborSearch {
 public:
  BruteForceSearch() = default;
  explicit BruteForceSearch(std::optional<PeriodicBox> box) : box_(box) {}
  void find_pairs(const std::vector<Vec3>& position, const std::vector<double>& radius, double margin,
                  PairList& out) override;

 private:
  std::optional<PeriodicBox> box_;
};

// Cell list on a hashed grid: cells of edge 2 R_max + margin are mapped into a table of about
// 2N buckets, so memory and time stay O(N) however far the particles spread (a break-up sends
// fragments in all directions; a dense grid over the bounding box would not stay O(N)). In a
// periodic box each axis holds n = floor(L / edge) >= 2 cells of edge L / n, and cell coordinates
// are taken modulo n, so the cells along a face neighbour those along the opposite face.
class CellListSearch final : public NeighborSearch {
 public:
  CellListSearch() = default;
  explicit CellListSearch(std::optional<PeriodicBox> box) : box_(box) {}
  void find_pairs(const std::vector<Vec3>& position, const std::vector<double>& radius, double margin,
                  PairList& out) override;

  struct Cell {
    std::int64_t x, y, z;
    friend bool operator==(const Cell&, const Cell&) = default;
  };

 private:
  template <class Grid>
  void find_pairs_on(const Grid& grid, const std::vector<Vec3>& position, const std::vector<double>& radius,
                     double margin, PairList& out);

  std::optional<PeriodicBox> box_;
  std::vector<Cell> cell_of_;
  std::vector<std::uint32_t> bucket_start_;
  std::vector<std::uint32_t> sorted_;
};

}  // namespace aerobreak
