// Timing of ballistic cluster-cluster aggregation (monodisperse) at a few sizes: clusters per
// second and seconds per cluster, each size repeated until at least a second has been spent.
// Then tunable (FracVAL) aggregation at Df = 1.8 and 2.6, likewise, and diffusion-limited
// aggregation grown by the engine (engine/growth, default parameters, sintered), one cluster per
// size: `bench_cluster [N ...]` (default 256 1024 4096).
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <utility>
#include <vector>

#include "engine/cluster/ballistic_aggregation.hpp"
#include "engine/cluster/tunable_aggregation.hpp"
#include "engine/growth/diffusion_limited_aggregation.hpp"

int main(int argc, char** argv) {
  using clock = std::chrono::steady_clock;
  std::vector<std::size_t> dlca_sizes;
  for (int a = 1; a < argc; ++a) dlca_sizes.push_back(static_cast<std::size_t>(std::strtoull(argv[a], nullptr, 10)));
  if (dlca_sizes.empty()) dlca_sizes = {256, 1024, 4096};
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

  // Tunable (FracVAL) aggregation, monodisperse, at a low and a high fractal dimension; each size
  // repeated until at least a second has been spent.
  for (const auto& [df, kf] : {std::pair{1.8, 1.3}, std::pair{2.6, 1.0}}) {
    std::printf("\nTunable (FracVAL), Df = %.1f, kf = %.1f\n%8s %10s %16s %18s\n", df, kf, "N", "clusters",
                "clusters/s", "seconds/cluster");
    for (std::size_t n : {256, 1024, 4096}) {
      int clusters = 0;
      const auto start = clock::now();
      double elapsed = 0.0;
      while (elapsed < 1.0 || clusters < 3) {
        aerobreak::tunable_cluster_aggregation({.primary_count = n, .fractal_dimension = df, .prefactor = kf}, seed++);
        ++clusters;
        elapsed = std::chrono::duration<double>(clock::now() - start).count();
      }
      std::printf("%8zu %10d %16.2f %18.6f\n", n, clusters, clusters / elapsed, elapsed / clusters);
    }
  }

  // DLCA grown by the engine with the rigid far field (the default for sintered growth), one
  // cluster per size; the time varies several-fold with the seed (the last clusters meet after an
  // exponentially distributed wait). Sizes from the command line (default 256 1024 4096).
  std::printf("\nDLCA (engine/growth, sintered, defaults: volume fraction %.3g, rigid far field)\n%8s %10s %16s %18s\n",
              aerobreak::DiffusionLimitedParameters{}.volume_fraction, "N", "clusters", "clusters/s",
              "seconds/cluster");
  for (std::size_t n : dlca_sizes) {
    aerobreak::DiffusionLimitedParameters p;
    p.primary_count = n;
    const auto start = clock::now();
    aerobreak::diffusion_limited_aggregation(p, 1);
    const double elapsed = std::chrono::duration<double>(clock::now() - start).count();
    std::printf("%8zu %10d %16.3g %18.1f\n", n, 1, 1.0 / elapsed, elapsed);
    std::fflush(stdout);
  }
  return 0;
}
