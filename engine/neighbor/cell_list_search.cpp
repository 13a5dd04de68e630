#include <algorithm>
#include <bit>
#include <cmath>

#include "engine/neighbor/neighbor_search.hpp"

namespace aerobreak {
namespace {

std::uint64_t cell_hash(std::int64_t x, std::int64_t y, std::int64_t z) {
  // Large odd multipliers spread neighbouring cells over the table (Teschner et al. 2003 style).
  return static_cast<std::uint64_t>(x) * 73856093ULL ^ static_cast<std::uint64_t>(y) * 19349663ULL ^
         static_cast<std::uint64_t>(z) * 83492791ULL;
}

}  // namespace

void CellListSearch::find_pairs(const std::vector<Vec3>& position, const std::vector<double>& radius, double margin,
                                PairList& out) {
  const std::size_t n = position.size();
  out.row_start.assign(n + 1, 0);
  out.neighbor.clear();
  if (n == 0) {
    out.contact.clear();
    return;
  }
  const double largest = *std::max_element(radius.begin(), radius.end());
  const double edge = 2.0 * largest + margin;
  const std::size_t buckets = std::bit_ceil(2 * n);
  const std::uint64_t mask = buckets - 1;

  // Counting sort of particles by bucket.
  cell_of_.resize(n);
  bucket_start_.assign(buckets + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& p = position[i];
    cell_of_[i] = {static_cast<std::int64_t>(std::floor(p.x / edge)), static_cast<std::int64_t>(std::floor(p.y / edge)),
                   static_cast<std::int64_t>(std::floor(p.z / edge))};
    ++bucket_start_[(cell_hash(cell_of_[i].x, cell_of_[i].y, cell_of_[i].z) & mask) + 1];
  }
  for (std::size_t b = 0; b < buckets; ++b) bucket_start_[b + 1] += bucket_start_[b];
  sorted_.resize(n);
  {
    std::vector<std::uint32_t> fill(bucket_start_.begin(), bucket_start_.end() - 1);
    for (std::size_t i = 0; i < n; ++i)
      sorted_[fill[cell_hash(cell_of_[i].x, cell_of_[i].y, cell_of_[i].z) & mask]++] = static_cast<std::uint32_t>(i);
  }

  for (std::size_t i = 0; i < n; ++i) {
    out.row_start[i] = static_cast<std::uint32_t>(out.neighbor.size());
    const Cell home = cell_of_[i];
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const Cell cell{home.x + dx, home.y + dy, home.z + dz};
          const std::uint64_t b = cell_hash(cell.x, cell.y, cell.z) & mask;
          for (std::uint32_t k = bucket_start_[b]; k < bucket_start_[b + 1]; ++k) {
            const std::uint32_t j = sorted_[k];
            // Another cell can share the bucket: take j only from its own cell, so once.
            if (j <= i || !(cell_of_[j] == cell)) continue;
            const double reach = radius[i] + radius[j] + margin;
            if (norm2(position[j] - position[i]) < reach * reach) out.neighbor.push_back(j);
          }
        }
    std::sort(out.neighbor.begin() + out.row_start[i], out.neighbor.end());
  }
  out.row_start[n] = static_cast<std::uint32_t>(out.neighbor.size());
  out.contact.assign(out.neighbor.size(), -1);
}

}  // namespace aerobreak
