#pragma once
#include <cstddef>
#include <map>
#include <utility>
#include <vector>

#include "engine/cluster/fractal_scaling_fit.hpp"
#include "engine/growth/contact_clusters.hpp"

namespace aerobreak {

// The clusters a growth run forms on its way, for ensemble fractal scaling (report figure 2b):
// recorded at every look (e.g. from the DiffusionLimitedProgress callback), each cluster keeps the
// radius of gyration of its reassembled centres (contact_clusters) at the last look before it grew
// into a larger one. One run of N primaries so yields up to N - 1 clusters of sizes 2..N (one
// history per run: the names below are particle indices, which another run reuses). They
// are not independent (a cluster contains its predecessors), so a fit's standard error is
// optimistic.
class GrowthHistory {
 public:
  explicit GrowthHistory(std::size_t smallest = 2) : smallest_(smallest) {}

  // Every cluster of a look, of primaries of one radius.
  void record(const std::vector<ContactCluster>& clusters, double primary_radius);
  // One sample per cluster seen with at least `smallest` primaries, final one included.
  std::vector<SizeRadiusSample> samples() const;

 private:
  std::size_t smallest_;
  // Keyed by (lowest member, size): a cluster only grows, so the pair names it until it merges.
  std::map<std::pair<std::size_t, std::size_t>, double> radius_;
};

}  // namespace aerobreak
