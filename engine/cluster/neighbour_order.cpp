#include "engine/cluster/neighbour_order.hpp"

#include <cstdint>
#include <vector>

#include "engine/cluster/cluster_contacts.hpp"

namespace aerobreak {
namespace {

// Adjacency in compressed-row form.
struct Adjacency {
  std::vector<std::size_t> start;
  std::vector<std::size_t> partner;
};

Adjacency adjacency(std::size_t n, const ContactGraph& graph) {
  Adjacency a;
  a.start.assign(n + 1, 0);
  for (const auto& [i, j] : graph.contacts) {
    ++a.start[i + 1];
    ++a.start[j + 1];
  }
  for (std::size_t i = 0; i < n; ++i) a.start[i + 1] += a.start[i];
  a.partner.resize(a.start[n]);
  std::vector<std::size_t> fill(a.start.begin(), a.start.end() - 1);
  for (const auto& [i, j] : graph.contacts) {
    a.partner[fill[i]++] = j;
    a.partner[fill[j]++] = i;
  }
  return a;
}

// Appends to `order` the primaries reachable from `root` whose mark is not `mark`, breadth-first,
// and marks them.
void breadth_first(const Adjacency& a, std::size_t root, std::vector<std::size_t>& marks, std::size_t mark,
                   std::vector<std::size_t>& order) {
  std::size_t next = order.size();
  order.push_back(root);
  marks[root] = mark;
  while (next < order.size()) {
    const std::size_t u = order[next++];
    for (std::size_t k = a.start[u]; k < a.start[u + 1]; ++k)
      if (marks[a.partner[k]] != mark) {
        marks[a.partner[k]] = mark;
        order.push_back(a.partner[k]);
      }
  }
}

}  // namespace

Cluster ordered_along_neighbours(const Cluster& cluster, double relative_reach) {
  const std::size_t n = cluster.size();
  const Adjacency a = adjacency(n, find_contacts(cluster, relative_reach));
  // Each component is walked three times: to find one end, the other end, and then in order.
  constexpr std::size_t unplaced = 0, placed = 1;
  std::vector<std::size_t> marks(n, unplaced);
  std::size_t walk = placed;
  std::vector<std::size_t> order, scratch;
  order.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (marks[i] == placed) continue;
    std::size_t end = i;
    for (int round = 0; round < 2; ++round) {
      scratch.clear();
      breadth_first(a, end, marks, ++walk, scratch);
      end = scratch.back();
    }
    breadth_first(a, end, marks, placed, order);
  }
  Cluster ordered;
  ordered.position.reserve(n);
  ordered.radius.reserve(n);
  for (std::size_t i : order) {
    ordered.position.push_back(cluster.position[i]);
    ordered.radius.push_back(cluster.radius[i]);
  }
  return ordered;
}

}  // namespace aerobreak
