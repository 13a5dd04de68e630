#include "engine/growth/growth_history.hpp"

#include <algorithm>

#include "engine/cluster/cluster_analysis.hpp"
#include "engine/growth/contact_clusters.hpp"

namespace aerobreak {

void GrowthHistory::record(const Simulation& simulation) {
  for (const ContactCluster& c : contact_clusters(simulation)) {
    if (c.members.size() < smallest_) continue;
    Cluster cluster{c.position, {}};
    for (std::size_t m : c.members) cluster.radius.push_back(simulation.particles().radius[m]);
    radius_[{*std::min_element(c.members.begin(), c.members.end()), c.members.size()}] = radius_of_gyration(cluster);
  }
}

std::vector<SizeRadiusSample> GrowthHistory::samples() const {
  std::vector<SizeRadiusSample> samples;
  for (const auto& [key, radius] : radius_) samples.push_back({static_cast<double>(key.second), radius});
  return samples;
}

}  // namespace aerobreak
