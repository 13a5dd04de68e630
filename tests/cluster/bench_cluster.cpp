// Timing of ballistic cluster-cluster aggregation (monodisperse) at a few sizes: clusters per
// second and seconds per cluster, each size repeated until at least a second has been spent.
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdio>

#include "engine/cluster/ballistic_aggregation.hpp"

int main() {
  using clock = std::chrono::steady_clock;
  std::printf("%8s %10s %16s %18s\n", "N", "clusters", "clusters/s", "seconds/cluster");
  std::uint64_t seed = 1;
  for (std::size_t n : {256, 1024, 4096}) {
    int clusters = 0;
    const auto start = clock::now();
    double elapsed = 0.0;
    while (elapsed < 1.0 || clusters < 3) {
      aerobreak::ballistic_cluster_cluster_aggregation({.primary_count = n}, seed++);
      ++clusters;
      elapsed = std::chrono::duration<double>(clock::now() - start).count();
    }
    std::printf("%8zu %10d %16.2f %18.6f\n", n, clusters, clusters / elapsed, elapsed / clusters);
  }
  return 0;
}
