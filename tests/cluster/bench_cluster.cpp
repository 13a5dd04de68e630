// Timing of ballistic cluster-cluster aggregation (monodisperse) at a few sizes: clusters per
// second and seconds per cluster, each size repeated until at least a second has been spent.
// Then tunable (FracVAL) aggregation at Df = 1.8 and 2.6, likewise, and diffusion-limited
// aggregation grown by the engine (engine/growth, default parameters, sintered), one cluster per
// size.
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <utility>

#include "engine/cluster/ballistic_aggregation.hpp"
#include "engine/cluster/tunable_aggregation.hpp"
#include "engine/growth/diffusion_limited_aggregation.hpp"

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

  // Tunable (FracVAL) aggregation, monodisperse, at a low and a high fractal dimension; each size
  // repeated until at least a second has been spent.
  for (const auto& [df, kf] : {std::pair{1.8, 1.3}, std::pair{2.6, 1.0}}) {
    std::printf("\nTunable (FracVAL), Df = %.1f, kf = %.1f\n%8s %10s %16s %18s\n", df, kf, "N",
                "clusters", "clusters/s", "seconds/cluster");
    for (std::size_t n : {256, 1024, 4096}) {
      int clusters = 0;
      const auto start = clock::now();
      double elapsed = 0.0;
      while (elapsed < 1.0 || clusters < 3) {
        aerobreak::tunable_cluster_aggregation(
            {.primary_count = n, .fractal_dimension = df, .prefactor = kf}, seed++);
        ++clusters;
        elapsed = std::chrono::duration<double>(clock::now() - start).count();
      }
      std::printf("%8zu %10d %16.2f %18.6f\n", n, clusters, clusters / elapsed, elapsed / clusters);
    }
  }

  // DLCA: one cluster at N = 64 and 256 (minutes; the time varies several-fold with the seed,
  // since the last two clusters meet after an exponentially distributed wait). At a fixed volume
  // fraction one cluster costs ~N^2.44: N primaries times a growth time ~N^(2 - 1/D_f) (free-
  // draining clusters, D ~ 1/n, collision radius ~n^(1/D_f)). The 1024 and 4096 rows are that
  // extrapolation from 256, not measurements, and at 1 % volume fraction such clusters would
  // also crowd the box (D_f rises); a dilute box costs more still.
  std::printf("\nDLCA (engine/growth, sintered, defaults)\n%8s %10s %16s %18s\n", "N", "clusters", "clusters/s",
              "seconds/cluster");
  double seconds_at_256 = 0.0;
  for (std::size_t n : {64, 256}) {
    aerobreak::DiffusionLimitedParameters p;
    p.primary_count = n;
    p.sintering = true;
    const auto start = clock::now();
    aerobreak::diffusion_limited_aggregation(p, 1);
    const double elapsed = std::chrono::duration<double>(clock::now() - start).count();
    std::printf("%8zu %10d %16.4f %18.2f\n", n, 1, 1.0 / elapsed, elapsed);
    seconds_at_256 = elapsed;
  }
  for (std::size_t n : {1024, 4096}) {
    const double estimate = seconds_at_256 * std::pow(static_cast<double>(n) / 256.0, 2.44);
    std::printf("%8zu %10s %16.2e %18.3g  (estimate, N^2.44 from 256)\n", n, "-", 1.0 / estimate, estimate);
  }
  return 0;
}
