#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "engine/cluster/ballistic_aggregation.hpp"
#include "engine/cluster/cluster_analysis.hpp"
#include "engine/cluster/cluster_contacts.hpp"

using namespace aerobreak;

namespace {

// A simple-cubic block of nx * ny * nz touching spheres.
Cluster lattice(int nx, int ny, int nz, double diameter) {
  Cluster c;
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j < ny; ++j) {
      for (int k = 0; k < nz; ++k) {
        c.position.push_back({i * diameter, j * diameter, k * diameter});
        c.radius.push_back(0.5 * diameter);
      }
    }
  }
  return c;
}

Cluster straight_chain(int n, double diameter) { return lattice(n, 1, 1, diameter); }

double brute_force_extent(const Cluster& c) {
  double best = 0.0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    for (std::size_t j = i; j < c.size(); ++j) {
      best = std::max(best, norm(c.position[i] - c.position[j]) + c.radius[i] + c.radius[j]);
    }
  }
  return best;
}

}  // namespace

TEST_CASE("Rg of a dimer of unit-diameter spheres is 0.5") {
  CHECK(radius_of_gyration(straight_chain(2, 1.0)) == Approx(0.5).epsilon(1e-14));
}

TEST_CASE("Rg of a straight chain is sqrt((n^2 - 1) / 12) d") {
  for (int n : {3, 10, 101}) {
    const double d = 1.7;
    const double expected = std::sqrt((n * n - 1) / 12.0) * d;
    CHECK(radius_of_gyration(straight_chain(n, d)) == Approx(expected).epsilon(1e-12));
  }
}

TEST_CASE("A filled cubic lattice has its analytic Rg, contacts, extent and filling factor") {
  const int m = 6;
  const double d = 1.0;
  const Cluster cube = lattice(m, m, m, d);
  const ClusterAnalysis a = analyse_cluster(cube);
  // Each axis is an independent chain of m points: Rg^2 = 3 (m^2 - 1) / 12 d^2.
  const double rg = std::sqrt(3.0 * (m * m - 1) / 12.0) * d;
  CHECK(a.primary_count == 216);
  CHECK(a.radius_of_gyration == Approx(rg).epsilon(1e-12));
  CHECK(norm(a.centre_of_mass - Vec3{2.5, 2.5, 2.5}) < 1e-12);
  CHECK(a.contact_count == 3u * m * m * (m - 1));
  CHECK(a.deep_overlap_count == 0);
  CHECK(a.mean_coordination_number == Approx(2.0 * 3 * m * m * (m - 1) / (m * m * m)));
  CHECK(a.component_sizes == std::vector<std::size_t>{216});
  CHECK(a.maximum_extent == Approx(std::sqrt(3.0) * (m - 1) * d + d).epsilon(1e-12));
  const double sphere = std::sqrt(5.0 / 3.0) * rg;
  const double phi = m * m * m * std::pow(0.5 * d, 3) / std::pow(sphere, 3);
  CHECK(a.filling_factor == Approx(phi).epsilon(1e-12));
  CHECK(a.porosity == Approx(1.0 - phi).epsilon(1e-12));
}

TEST_CASE("Mass-radius dimension of lattices of dimension 1, 2 and 3") {
  // Centres near the edge see truncated neighbourhoods, which biases finite lattices ~5% low at
  // r = Rg/2 (measured: chain 0.95, sheet 1.90, cube 2.83).
  CHECK(mass_radius_dimension(lattice(200, 1, 1, 1.0)) == Approx(1.0).margin(0.1));
  CHECK(mass_radius_dimension(lattice(48, 48, 1, 1.0)) == Approx(2.0).margin(0.2));
  CHECK(mass_radius_dimension(lattice(20, 20, 20, 1.0)) == Approx(3.0).margin(0.3));
  // Too short a range of r (Rg < 8 d) gives no estimate.
  CHECK(std::isnan(mass_radius_dimension(straight_chain(20, 1.0))));
}

TEST_CASE("A chain has n - 1 contacts, extent n d and splits where a gap opens") {
  Cluster chain = straight_chain(8, 1.0);
  const ClusterAnalysis a = analyse_cluster(chain);
  CHECK(a.contact_count == 7);
  CHECK(a.mean_coordination_number == Approx(14.0 / 8.0));
  CHECK(a.maximum_extent == Approx(8.0).epsilon(1e-14));
  CHECK(std::isnan(analyse_cluster(straight_chain(1, 1.0)).filling_factor));

  for (std::size_t i = 5; i < chain.size(); ++i) chain.position[i].x += 0.01;
  CHECK(analyse_cluster(chain).component_sizes == std::vector<std::size_t>{5, 3});
}

TEST_CASE("Contacts follow the relative tolerance and count deeper overlaps") {
  const auto pair_at = [](double distance) { return Cluster{{Vec3{}, Vec3{distance, 0.0, 0.0}}, {0.5, 0.5}}; };
  CHECK(find_contacts(pair_at(1.0 + 0.9e-3)).contacts.size() == 1);
  CHECK(find_contacts(pair_at(1.0 + 1.1e-3)).contacts.empty());
  CHECK(find_contacts(pair_at(1.0 - 0.9e-3)).deep_overlap_count == 0);
  const ContactGraph deep = find_contacts(pair_at(0.9));
  CHECK(deep.contacts.size() == 1);
  CHECK(deep.deep_overlap_count == 1);
  CHECK(find_contacts(pair_at(1.0 + 1e-6), 1e-9).contacts.empty());
  CHECK(find_contacts(pair_at(1.0 + 1e-2), 0.02).contacts.size() == 1);
}

TEST_CASE("Contact search matches brute force on a polydisperse BCCA cluster") {
  const Cluster c =
      ballistic_cluster_cluster_aggregation({.primary_count = 400, .geometric_standard_deviation = 1.8}, 99);
  const double tol = 0.05;
  std::vector<std::pair<std::size_t, std::size_t>> expected;
  for (std::size_t i = 0; i < c.size(); ++i) {
    for (std::size_t j = i + 1; j < c.size(); ++j) {
      if (norm(c.position[i] - c.position[j]) <= (1.0 + tol) * (c.radius[i] + c.radius[j])) {
        expected.emplace_back(i, j);
      }
    }
  }
  CHECK(find_contacts(c, tol).contacts == expected);
}

TEST_CASE("Centre of mass and Rg weight primaries by r^3") {
  const Cluster c{{Vec3{}, Vec3{1.5, 0.0, 0.0}}, {1.0, 0.5}};
  const double x = 0.125 * 1.5 / 1.125;
  CHECK(centre_of_mass(c).x == Approx(x).epsilon(1e-14));
  const double rg2 = (1.0 * x * x + 0.125 * (1.5 - x) * (1.5 - x)) / 1.125;
  CHECK(radius_of_gyration(c) == Approx(std::sqrt(rg2)).epsilon(1e-14));
}

TEST_CASE("Maximum extent equals the brute-force pair maximum on BCCA clusters") {
  for (double sigma_g : {1.0, 2.0}) {
    const Cluster c =
        ballistic_cluster_cluster_aggregation({.primary_count = 700, .geometric_standard_deviation = sigma_g}, 5);
    CHECK(maximum_extent(c) == Approx(brute_force_extent(c)).epsilon(1e-14));
  }
}

TEST_CASE("Analysis rejects an empty cluster and a bad tolerance") {
  const Cluster empty;
  CHECK_THROWS_AS(analyse_cluster(empty), std::invalid_argument);
  CHECK_THROWS_AS(radius_of_gyration(empty), std::invalid_argument);
  CHECK_THROWS_AS(maximum_extent(empty), std::invalid_argument);
  CHECK_THROWS_AS(find_contacts(straight_chain(3, 1.0), -1e-3), std::invalid_argument);
}
