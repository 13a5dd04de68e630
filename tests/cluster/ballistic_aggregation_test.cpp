#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

#include "engine/cluster/ballistic_aggregation.hpp"
#include "engine/cluster/cluster_analysis.hpp"
#include "engine/cluster/cluster_contacts.hpp"

using namespace aerobreak;

namespace {

// A BCCA cluster is built from exact first touches, so every contact sits at r_i + r_j to rounding
// (~1e-14 relative); 1e-9 is far above rounding and far below any physical gap.
constexpr double exact_touch = 1e-9;

void require_one_rigid_touching_cluster(const Cluster& c, std::size_t n) {
  REQUIRE(c.size() == n);
  REQUIRE(c.radius.size() == n);
  const ContactGraph graph = find_contacts(c, exact_touch);
  CHECK(graph.deep_overlap_count == 0);
  CHECK(graph.contacts.size() >= n - 1);
  CHECK(connected_component_sizes(n, graph.contacts) == std::vector<std::size_t>{n});
  CHECK(norm(centre_of_mass(c)) <= 1e-9 * (1.0 + radius_of_gyration(c)));
}

}  // namespace

TEST_CASE("BCCA clusters are one connected component of exactly touching primaries") {
  for (std::size_t n : {1, 2, 3, 7, 64, 100, 500}) {
    INFO("N = " << n);
    const Cluster c = ballistic_cluster_cluster_aggregation({.primary_count = n}, 42 + n);
    require_one_rigid_touching_cluster(c, n);
    for (double r : c.radius) CHECK(r == 0.5);
  }
}

TEST_CASE("BCCA with lognormal radii is connected, touching and overlap-free") {
  for (std::size_t n : {2, 3, 7, 64, 100, 500}) {
    INFO("N = " << n);
    const Cluster c = ballistic_cluster_cluster_aggregation(
        {.primary_count = n, .geometric_mean_diameter = 2.0, .geometric_standard_deviation = 1.6}, 7 * n);
    require_one_rigid_touching_cluster(c, n);
  }
}

TEST_CASE("BCCA lognormal diameters have the requested geometric mean and deviation") {
  const double dg = 30.0;
  const double sigma_g = 1.5;
  const std::size_t n = 4000;
  const Cluster c = ballistic_cluster_cluster_aggregation(
      {.primary_count = n, .geometric_mean_diameter = dg, .geometric_standard_deviation = sigma_g}, 2024);
  double mean_log = 0.0;
  for (double r : c.radius) mean_log += std::log(2.0 * r);
  mean_log /= n;
  double variance = 0.0;
  for (double r : c.radius) variance += std::pow(std::log(2.0 * r) - mean_log, 2);
  variance /= n - 1;
  // Sampling error of the mean of ln d is ln(1.5)/sqrt(4000) ~ 0.0064; allow 5 of those.
  CHECK(mean_log == Approx(std::log(dg)).margin(0.032));
  CHECK(std::sqrt(variance) == Approx(std::log(sigma_g)).epsilon(0.05));
}

TEST_CASE("BCCA is reproducible bit for bit from its seed") {
  const BallisticAggregationParameters p{.primary_count = 300, .geometric_standard_deviation = 1.3};
  const Cluster a = ballistic_cluster_cluster_aggregation(p, 123456789);
  const Cluster b = ballistic_cluster_cluster_aggregation(p, 123456789);
  const Cluster other = ballistic_cluster_cluster_aggregation(p, 123456790);
  CHECK(a.position == b.position);
  CHECK(a.radius == b.radius);
  CHECK(a.position != other.position);
  CHECK(a.radius != other.radius);
}

TEST_CASE("BCCA rejects bad parameters, naming them") {
  using Catch::Contains;
  const auto run = [](BallisticAggregationParameters p) { return ballistic_cluster_cluster_aggregation(p, 1); };
  REQUIRE_THROWS_WITH(run({.primary_count = 0}), Contains("primary_count"));
  REQUIRE_THROWS_WITH(run({.primary_count = 4, .geometric_mean_diameter = 0.0}), Contains("geometric_mean_diameter"));
  REQUIRE_THROWS_WITH(run({.primary_count = 4, .geometric_mean_diameter = -1.0}), Contains("geometric_mean_diameter"));
  REQUIRE_THROWS_WITH(run({.primary_count = 4, .geometric_mean_diameter = std::nan("")}),
                      Contains("geometric_mean_diameter"));
  REQUIRE_THROWS_WITH(run({.primary_count = 4, .geometric_standard_deviation = 0.9}),
                      Contains("geometric_standard_deviation"));
  REQUIRE_THROWS_AS(run({.primary_count = 0}), std::invalid_argument);
}
