#include "engine/cluster/cluster_contacts.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <stdexcept>

#include "engine/core/disjoint_sets.hpp"

namespace aerobreak {
namespace {

// Primaries sorted by a packed (ix, iy, iz) cell key; the neighbours of a primary lie in the 27
// cells around its own, each found by binary search. Memory is O(N) however sparse the cluster.
class CellList {
 public:
  CellList(const Cluster& cluster, double cell_size) : cell_(cell_size) {
    origin_ = cluster.position.front();
    Vec3 top = origin_;
    for (const Vec3& x : cluster.position) {
      origin_ = {std::min(origin_.x, x.x), std::min(origin_.y, x.y), std::min(origin_.z, x.z)};
      top = {std::max(top.x, x.x), std::max(top.y, x.y), std::max(top.z, x.z)};
    }
    // Keep every axis index below 2^21 so three of them pack into one 64-bit key.
    const double span = std::max({top.x - origin_.x, top.y - origin_.y, top.z - origin_.z});
    cell_ = std::max(cell_, span / static_cast<double>(max_index - 2));

    entries_.reserve(cluster.size());
    for (std::size_t i = 0; i < cluster.size(); ++i) {
      entries_.push_back({key(cell_of(cluster.position[i])), i});
    }
    std::sort(entries_.begin(), entries_.end());
  }

  // Calls visit(j) for every primary j in the 27 cells around point x.
  template <class Visit>
  void for_each_near(const Vec3& x, Visit&& visit) const {
    const CellIndex c = cell_of(x);
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const CellIndex n{c.x + dx, c.y + dy, c.z + dz};
          if (n.x < 0 || n.y < 0 || n.z < 0) continue;
          const Entry probe{key(n), 0};
          auto it = std::lower_bound(entries_.begin(), entries_.end(), probe);
          for (; it != entries_.end() && it->key == probe.key; ++it) visit(it->index);
        }
      }
    }
  }

 private:
  static constexpr std::int64_t max_index = std::int64_t{1} << 21;
  struct CellIndex {
    std::int64_t x, y, z;
  };
  struct Entry {
    std::uint64_t key;
    std::size_t index;
    friend auto operator<=>(const Entry&, const Entry&) = default;
  };

  CellIndex cell_of(const Vec3& x) const {
    return {static_cast<std::int64_t>((x.x - origin_.x) / cell_), static_cast<std::int64_t>((x.y - origin_.y) / cell_),
            static_cast<std::int64_t>((x.z - origin_.z) / cell_)};
  }
  static std::uint64_t key(const CellIndex& c) {
    return (static_cast<std::uint64_t>(c.x) << 42) | (static_cast<std::uint64_t>(c.y) << 21) |
           static_cast<std::uint64_t>(c.z);
  }

  double cell_;
  Vec3 origin_;
  std::vector<Entry> entries_;
};

}  // namespace

ContactGraph find_contacts(const Cluster& cluster, double relative_tolerance) {
  if (!(relative_tolerance >= 0.0) || !std::isfinite(relative_tolerance)) {
    throw std::invalid_argument("find_contacts: relative_tolerance must be >= 0 and finite");
  }
  ContactGraph graph;
  if (cluster.size() < 2) return graph;

  const double largest = *std::max_element(cluster.radius.begin(), cluster.radius.end());
  const CellList cells(cluster, 2.0 * largest * (1.0 + relative_tolerance));
  for (std::size_t i = 0; i < cluster.size(); ++i) {
    const Vec3& xi = cluster.position[i];
    cells.for_each_near(xi, [&](std::size_t j) {
      if (j <= i) return;
      const double touching = cluster.radius[i] + cluster.radius[j];
      const double distance = norm(cluster.position[j] - xi);
      if (distance > (1.0 + relative_tolerance) * touching) return;
      graph.contacts.emplace_back(i, j);
      if (distance < (1.0 - relative_tolerance) * touching) ++graph.deep_overlap_count;
    });
  }
  std::sort(graph.contacts.begin(), graph.contacts.end());
  return graph;
}

std::optional<PrimaryOverlap> find_overlap_beyond(const Cluster& cluster, double fraction) {
  if (cluster.size() < 2) return std::nullopt;
  const double largest = *std::max_element(cluster.radius.begin(), cluster.radius.end());
  const CellList cells(cluster, 2.0 * largest);
  std::optional<PrimaryOverlap> found;
  for (std::size_t i = 0; i < cluster.size() && !found; ++i) {
    const Vec3& xi = cluster.position[i];
    cells.for_each_near(xi, [&](std::size_t j) {
      if (found || j <= i) return;
      const double smaller = std::min(cluster.radius[i], cluster.radius[j]);
      const double overlap = cluster.radius[i] + cluster.radius[j] - norm(cluster.position[j] - xi);
      if (overlap > fraction * smaller) found = PrimaryOverlap{i, j, overlap, smaller};
    });
  }
  return found;
}

std::vector<std::size_t> connected_component_sizes(std::size_t primary_count,
                                                   const std::vector<std::pair<std::size_t, std::size_t>>& edges) {
  DisjointSets sets(primary_count);
  for (const auto& [i, j] : edges) sets.unite(i, j);
  std::vector<std::size_t> size_of_root(primary_count, 0);
  for (std::size_t i = 0; i < primary_count; ++i) ++size_of_root[sets.find(i)];
  std::vector<std::size_t> sizes;
  for (std::size_t s : size_of_root) {
    if (s > 0) sizes.push_back(s);
  }
  std::sort(sizes.begin(), sizes.end(), std::greater<>());
  return sizes;
}

}  // namespace aerobreak
