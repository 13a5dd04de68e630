#pragma once
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "engine/core/vec3.hpp"
#include "engine/neighbor/neighbor_search.hpp"
#include "engine/neighbor/pair_list.hpp"
#include "engine/neighbor/periodic_box.hpp"

namespace aerobreak {

// A sphere about a group of particles that holds all of them (reach < 0: none known).
struct BoundingSphere {
  Vec3 centre;
  double reach = -1.0;
};

// How close the groups of particles in a periodic box come to one another: for each group, the
// smallest surface gap |x_i - x_j| - R_i - R_j to a particle of another group (nearest images),
// and the pairs of groups closer than a threshold.
struct GroupProximity {
  // Per group: the exact smallest gap where it is below the search gap; otherwise a lower bound,
  // the search gap or, where every group has a bounding sphere, the gap between spheres if larger.
  std::vector<double> gap;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> close;  // (a, b), a < b, each pair once
};

// Particle pairs within the search gap come from a cell list (neighbor/); groups without a
// partner among them are bounded by their bounding spheres (for up to `sphere_limit` groups, an
// O(groups^2) pass), so that a few large clusters far apart see how far apart they are.
class GroupProximitySearch {
 public:
  GroupProximitySearch(const PeriodicBox& box, double search_gap, std::size_t sphere_limit = 256);

  // `group` numbers each particle's group, 0 .. groups - 1; `spheres` is empty or one per group.
  GroupProximity find(const std::vector<Vec3>& position, const std::vector<double>& radius,
                      const std::vector<std::uint32_t>& group, std::size_t groups,
                      const std::vector<BoundingSphere>& spheres, double close_gap);

  double search_gap() const { return search_gap_; }

 private:
  PeriodicBox box_;
  double search_gap_;
  std::size_t sphere_limit_;
  CellListSearch search_;
  PairList pairs_;
};

}  // namespace aerobreak
