// How far this core's caches reach: the rate at which one core reads and writes back arrays of
// growing size (the access pattern of the engine's passes over particles and contacts). Where the
// rate falls, the working set has left the caches; docs/PERFORMANCE.md compares that size with the
// engine's bytes per primary.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

int main() {
  std::printf("%10s %22s\n", "MiB", "GB/s (read + write)");
  for (double mib : {0.5, 2.0, 4.0, 8.0, 12.0, 16.0, 24.0, 32.0, 64.0}) {
    const auto n = static_cast<std::size_t>(mib * 1024 * 1024 / sizeof(double));
    std::vector<double> column(n, 1.0);
    const std::size_t sweeps = std::max<std::size_t>(1, static_cast<std::size_t>(256.0 / mib));
    double best = 1e300;
    for (int repeat = 0; repeat < 7; ++repeat) {
      const auto start = std::chrono::steady_clock::now();
      for (std::size_t s = 0; s < sweeps; ++s)
        for (double& x : column) x = x * 1.0000001 + 1e-9;
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      best = std::min(best, seconds / static_cast<double>(sweeps));
    }
    // The result is printed so that the sweeps cannot be optimised away.
    std::printf("%10.1f %22.1f   (checksum %.6g)\n", mib, 2.0 * static_cast<double>(n * sizeof(double)) / best / 1e9,
                column[n / 2]);
  }
}
