#include "engine/growth/growth_history.hpp"

#include <algorithm>

#include "engine/cluster/cluster_analysis.hpp"

namespace aerobreak {

void GrowthHistory::record(const std::vector<ContactCluster>& clusters, double primary_radius) {
  for (const ContactCluster& c : clusters) {
    if (c.members.size() < smallest_) continue;
    const Cluster cluster{c.position, std::vector<double>(c.members.size(), primary_radius)};
    radius_[{*std::min_element(c.members.begin(), c.members.end()), c.members.size()}] = radius_of_gyration(cluster);
  }
}

std::vector<SizeRadiusSample> GrowthHistory::samples() const {
  std::vector<SizeRadiusSample> samples;
  for (const auto& [key, radius] : radius_) samples.push_back({static_cast<double>(key.second), radius});
  return samples;
}

}  // namespace aerobreak
