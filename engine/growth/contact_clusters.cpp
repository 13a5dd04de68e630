#include "engine/growth/contact_clusters.hpp"

#include <algorithm>

namespace aerobreak {

std::vector<std::pair<std::size_t, std::size_t>> contact_edges(const Simulation& simulation) {
  std::vector<std::pair<std::size_t, std::size_t>> edges;
  simulation.contacts().for_each([&](const ContactState& c) {
    if (!c.with_wall) edges.emplace_back(std::min(c.i, c.j), std::max(c.i, c.j));
  });
  return edges;
}

std::vector<ContactCluster> contact_clusters(const Simulation& simulation) {
  const std::size_t n = simulation.particles().size();
  const auto edges = contact_edges(simulation);
  std::vector<std::vector<std::size_t>> neighbours(n);
  for (const auto& [i, j] : edges) {
    neighbours[i].push_back(j);
    neighbours[j].push_back(i);
  }
  const std::vector<Vec3> unwrapped = simulation.unwrapped_positions();
  constexpr std::size_t unplaced = static_cast<std::size_t>(-1);
  std::vector<std::size_t> component(n, unplaced);
  std::vector<Vec3> placed(n);
  std::vector<ContactCluster> clusters;
  for (std::size_t root = 0; root < n; ++root) {
    if (component[root] != unplaced) continue;
    ContactCluster cluster;
    component[root] = clusters.size();
    placed[root] = unwrapped[root];
    cluster.members.push_back(root);
    // Breadth-first: members is also the queue.
    for (std::size_t head = 0; head < cluster.members.size(); ++head) {
      const std::size_t i = cluster.members[head];
      for (std::size_t j : neighbours[i]) {
        if (component[j] != unplaced) continue;
        component[j] = clusters.size();
        placed[j] = placed[i] + simulation.separation(i, j);
        cluster.members.push_back(j);
      }
    }
    for (std::size_t m : cluster.members) cluster.position.push_back(placed[m]);
    clusters.push_back(std::move(cluster));
  }
  // A contact whose ends, as placed, are not its nearest-image separation apart wraps around
  // the box (they differ by a box vector, so half the shortest edge separates the two cases).
  const auto& box = simulation.periodic_box();
  for (const auto& [i, j] : edges) {
    ContactCluster& cluster = clusters[component[i]];
    ++cluster.contacts;
    if (box && norm(placed[j] - placed[i] - simulation.separation(i, j)) > 0.5 * box->shortest_edge())
      ++cluster.image_contacts;
  }
  std::stable_sort(clusters.begin(), clusters.end(), [](const ContactCluster& a, const ContactCluster& b) {
    return a.members.size() > b.members.size();
  });
  return clusters;
}

}  // namespace aerobreak
