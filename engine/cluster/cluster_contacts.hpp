#pragma once
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "engine/cluster/cluster.hpp"

namespace aerobreak {

// The contact graph of a cluster. Primaries i and j are in contact when their surfaces are within
// a relative tolerance of touching, |r_ij - (r_i + r_j)| <= tol (r_i + r_j), or overlap more deeply
// than that, r_ij < (1 - tol)(r_i + r_j); the deeper overlaps are also counted separately.
struct ContactGraph {
  std::vector<std::pair<std::size_t, std::size_t>> contacts;  // (i, j) with i < j
  std::size_t deep_overlap_count = 0;
};

// Found with a cell list (sorted cell keys, cell size = the largest contact reach), O(N log N).
// Throws std::invalid_argument for a negative or non-finite tolerance.
ContactGraph find_contacts(const Cluster& cluster, double relative_tolerance = 1e-3);

// A pair of primaries (i < j) that overlap by `overlap` = r_i + r_j - |x_i - x_j|.
struct PrimaryOverlap {
  std::size_t i = 0, j = 0;
  double overlap = 0.0;
  double smaller_radius = 0.0;
};

// The first pair (in the order of i) whose overlap exceeds `fraction` of the smaller radius of the
// two; nullopt when no pair does. The same cell list as find_contacts, and the search ends at the
// first such pair, so that a file of a million primaries at one point is refused at once.
std::optional<PrimaryOverlap> find_overlap_beyond(const Cluster& cluster, double fraction);

// Sizes of the connected components of the graph on primary_count vertices, largest first
// (isolated primaries are components of size 1). Union-find with path halving.
std::vector<std::size_t> connected_component_sizes(std::size_t primary_count,
                                                   const std::vector<std::pair<std::size_t, std::size_t>>& edges);

}  // namespace aerobreak
