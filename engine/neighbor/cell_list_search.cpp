#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <span>

#include "engine/neighbor/neighbor_search.hpp"

namespace aerobreak {
namespace {

using Cell = CellListSearch::Cell;

std::uint64_t cell_hash(const Cell& c) {
  // Large odd multipliers spread neighbouring cells over the table (Teschner et al. 2003 style).
  return static_cast<std::uint64_t>(c.x) * 73856093ULL ^ static_cast<std::uint64_t>(c.y) * 19349663ULL ^
         static_cast<std::uint64_t>(c.z) * 83492791ULL;
}

// Unbounded cells of edge h in open space: cell = floor(x / h), neighbours at offsets -1, 0, 1.
struct OpenGrid {
  double edge;

  Cell cell(const Vec3& p) const {
    return {static_cast<std::int64_t>(std::floor(p.x / edge)), static_cast<std::int64_t>(std::floor(p.y / edge)),
            static_cast<std::int64_t>(std::floor(p.z / edge))};
  }
  Cell shifted(const Cell& c, std::int64_t dx, std::int64_t dy, std::int64_t dz) const {
    return {c.x + dx, c.y + dy, c.z + dz};
  }
  static constexpr std::array<std::int64_t, 3> offsets{-1, 0, 1};
  std::span<const std::int64_t> offsets_along(int) const { return offsets; }
  OpenSpace separation;
};

// n_a = floor(L_a / edge) cells along axis a, coordinates modulo n_a. With two cells along an
// axis the offsets -1 and +1 name the same cell, so only 0 and +1 are visited there.
struct PeriodicGrid {
  explicit PeriodicGrid(const PeriodicBox& box, double edge) : separation(box) {
    const double lengths[3] = {box.length.x, box.length.y, box.length.z};
    for (int a = 0; a < 3; ++a) {
      count[a] = std::max<std::int64_t>(1, static_cast<std::int64_t>(std::floor(lengths[a] / edge)));
      per_length[a] = static_cast<double>(count[a]) / lengths[a];
      span_of[a] = count[a] >= 3 ? 3 : count[a];
    }
  }

  static std::int64_t modulo(std::int64_t k, std::int64_t n) { return ((k % n) + n) % n; }
  Cell cell(const Vec3& p) const {
    return {modulo(static_cast<std::int64_t>(std::floor(p.x * per_length[0])), count[0]),
            modulo(static_cast<std::int64_t>(std::floor(p.y * per_length[1])), count[1]),
            modulo(static_cast<std::int64_t>(std::floor(p.z * per_length[2])), count[2])};
  }
  Cell shifted(const Cell& c, std::int64_t dx, std::int64_t dy, std::int64_t dz) const {
    return {modulo(c.x + dx, count[0]), modulo(c.y + dy, count[1]), modulo(c.z + dz, count[2])};
  }
  std::span<const std::int64_t> offsets_along(int axis) const {
    static constexpr std::array<std::int64_t, 3> all{-1, 0, 1};
    return span_of[axis] == 3 ? std::span<const std::int64_t>(all)
                              : std::span<const std::int64_t>(all).subspan(1, static_cast<std::size_t>(span_of[axis]));
  }

  std::int64_t count[3];
  double per_length[3];
  std::int64_t span_of[3];
  PeriodicSpace separation;
};

}  // namespace

void CellListSearch::find_pairs(const std::vector<Vec3>& position, const std::vector<double>& radius, double margin,
                                PairList& out) {
  if (position.empty()) {
    out.row_start.assign(1, 0);
    out.neighbor.clear();
    out.contact.clear();
    return;
  }
  const double largest = *std::max_element(radius.begin(), radius.end());
  const double edge = 2.0 * largest + margin;
  if (box_) {
    box_->require_single_image(edge);
    find_pairs_on(PeriodicGrid(*box_, edge), position, radius, margin, out);
  } else {
    find_pairs_on(OpenGrid{edge, OpenSpace{}}, position, radius, margin, out);
  }
}

template <class Grid>
void CellListSearch::find_pairs_on(const Grid& grid, const std::vector<Vec3>& position,
                                   const std::vector<double>& radius, double margin, PairList& out) {
  const std::size_t n = position.size();
  out.row_start.assign(n + 1, 0);
  out.neighbor.clear();
  const std::size_t buckets = std::bit_ceil(2 * n);
  const std::uint64_t mask = buckets - 1;

  // Counting sort of particles by bucket.
  cell_of_.resize(n);
  bucket_start_.assign(buckets + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    cell_of_[i] = grid.cell(position[i]);
    ++bucket_start_[(cell_hash(cell_of_[i]) & mask) + 1];
  }
  for (std::size_t b = 0; b < buckets; ++b) bucket_start_[b + 1] += bucket_start_[b];
  sorted_.resize(n);
  {
    std::vector<std::uint32_t> fill(bucket_start_.begin(), bucket_start_.end() - 1);
    for (std::size_t i = 0; i < n; ++i) sorted_[fill[cell_hash(cell_of_[i]) & mask]++] = static_cast<std::uint32_t>(i);
  }

  for (std::size_t i = 0; i < n; ++i) {
    out.row_start[i] = static_cast<std::uint32_t>(out.neighbor.size());
    const Cell home = cell_of_[i];
    for (std::int64_t dx : grid.offsets_along(0))
      for (std::int64_t dy : grid.offsets_along(1))
        for (std::int64_t dz : grid.offsets_along(2)) {
          const Cell cell = grid.shifted(home, dx, dy, dz);
          const std::uint64_t b = cell_hash(cell) & mask;
          for (std::uint32_t k = bucket_start_[b]; k < bucket_start_[b + 1]; ++k) {
            const std::uint32_t j = sorted_[k];
            // Another cell can share the bucket: take j only from its own cell, so once.
            if (j <= i || !(cell_of_[j] == cell)) continue;
            const double reach = radius[i] + radius[j] + margin;
            if (norm2(grid.separation(position[j] - position[i])) < reach * reach) out.neighbor.push_back(j);
          }
        }
    std::sort(out.neighbor.begin() + out.row_start[i], out.neighbor.end());
  }
  out.row_start[n] = static_cast<std::uint32_t>(out.neighbor.size());
  out.contact.assign(out.neighbor.size(), -1);
}

}  // namespace aerobreak
