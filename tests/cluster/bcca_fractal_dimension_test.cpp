#include <catch2/catch.hpp>

#include <cstdint>
#include <vector>

#include "engine/cluster/ballistic_aggregation.hpp"
#include "engine/cluster/cluster_analysis.hpp"
#include "engine/cluster/fractal_scaling_fit.hpp"

using namespace aerobreak;

TEST_CASE("BCCA ensemble fractal dimension lies in the literature range") {
  std::vector<SizeRadiusSample> samples;
  std::uint64_t seed = 1000;
  for (std::size_t n : {32, 64, 128, 256, 512, 1024, 2048}) {
    for (int replicate = 0; replicate < 64; ++replicate) {
      const Cluster c = ballistic_cluster_cluster_aggregation({.primary_count = n}, seed++);
      samples.push_back({static_cast<double>(n), radius_of_gyration(c)});
    }
  }
  const FractalScalingFit fit = fit_fractal_scaling(samples, 0.5);
  INFO("D_f = " << fit.fractal_dimension << " +- " << fit.fractal_dimension_standard_error
                << ", k_f = " << fit.prefactor);
  // Hierarchical BCCA gives D_f ~ 1.9 (Jullien 1984) and the report's generator ~2.05 (figure
  // 2b). ln Rg scatters by ~0.14 from cluster to cluster, so 64 clusters per size are needed: the
  // fit then reports a standard error of ~0.017 (8 per size gave ~0.06, and base seeds whose D_f
  // fell 2.5 standard errors low, at 1.73). This ensemble measures D_f = 1.89 (spread 1.85-1.93
  // over 20 base seeds), so the lower bound 1.80 sits ~5 standard errors below it and the upper
  // bound 2.15 (the report's 2.05 plus ~6 standard errors) far above. DLCA (~1.78) falls just
  // below, compact structure or a wrong Rg far outside.
  CHECK(fit.fractal_dimension_standard_error < 0.03);
  CHECK(fit.fractal_dimension > 1.80);
  CHECK(fit.fractal_dimension < 2.15);
}

TEST_CASE("Mass-radius dimension of one large BCCA cluster is near 2") {
  const Cluster c = ballistic_cluster_cluster_aggregation({.primary_count = 4096}, 77);
  const double d = mass_radius_dimension(c);
  INFO("mass-radius D = " << d);
  // Looser than the ensemble band: one realisation, no ensemble average, and only about a decade of
  // r (2 d to Rg/2 ~ 20 d) over which the local slope is not constant (near 1.9 at a few d, then
  // falling as the cluster's edge cuts M(r) off). Measured single-cluster values spread 1.81-1.93
  // over 8 seeds at N = 4096 and 1.73-2.00 at N = 1024.
  CHECK(d > 1.6);
  CHECK(d < 2.3);
}
