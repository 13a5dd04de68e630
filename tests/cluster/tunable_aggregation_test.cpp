#include "engine/cluster/tunable_aggregation.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/cluster/cluster_analysis.hpp"
#include "engine/cluster/cluster_contacts.hpp"
#include "engine/cluster/fractal_scaling_fit.hpp"
#include "engine/cluster/tunable_feasibility.hpp"
#include "engine/cluster/tunable_free_arcs.hpp"
#include "engine/cluster/tunable_scaling_law.hpp"

using namespace aerobreak;

namespace {

// Rg of solid spheres (FracVAL eq. 4), computed here from the project's point-mass analysis:
// Rg_solid^2 = Rg_point^2 + (3/5) sum m r^2 / sum m, m ~ r^3.
double solid_sphere_gyration_radius(const Cluster& c) {
  double mass = 0.0;
  double own = 0.0;
  for (double r : c.radius) {
    mass += r * r * r;
    own += 0.6 * r * r * r * r * r;
  }
  const double point = radius_of_gyration(c);
  return std::sqrt(point * point + own / mass);
}

double geometric_mean(const std::vector<double>& radii) {
  double sum = 0.0;
  for (double r : radii) sum += std::log(r);
  return std::exp(sum / static_cast<double>(radii.size()));
}

// The scaling law's Rg for the cluster: a (N / kf)^(1 / Df), a the geometric mean primary radius.
double law_gyration_radius(const Cluster& c, double df, double kf) {
  return geometric_mean(c.radius) * std::pow(static_cast<double>(c.size()) / kf, 1.0 / df);
}

// Smallest centre distance over contact distance, all pairs (brute force, independent of the
// generator's cell grid).
double closest_approach(const Cluster& c) {
  double closest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < c.size(); ++i) {
    for (std::size_t j = i + 1; j < c.size(); ++j) {
      closest = std::min(closest, norm(c.position[i] - c.position[j]) / (c.radius[i] + c.radius[j]));
    }
  }
  return closest;
}

std::size_t component_count(const Cluster& c) {
  return connected_component_sizes(c.size(), find_contacts(c, 1e-9).contacts).size();
}

struct Request {
  double df;
  double kf;
};

// kf per Df inside the window the smallest aggregates allow (tunable_feasibility.hpp; FracVAL
// uses kf ~ 1-1.4): at Df = 1.6 kf must be at least 1.16, at Df = 2.6 at most 1.27.
const std::vector<Request> requests = {{1.6, 1.3}, {1.8, 1.0}, {1.8, 1.3}, {2.0, 1.0},
                                       {2.0, 1.3}, {2.3, 1.3}, {2.6, 1.0}};

}  // namespace

TEST_CASE("Tunable clusters have the scaling law's Rg, no overlaps and one component") {
  // Construction is exact: every join puts the centres of mass at the Gamma that gives the union
  // the law's Rg, so only round-off remains (measured below 1e-13). The 1e-9 bound is the
  // generator's own check; a monomer misplaced by 1e-6 d would already exceed it.
  std::uint64_t seed = 11;
  for (const Request& q : requests) {
    for (double sigma : {1.0, 1.25}) {
      const TunableAggregationParameters p{
          .primary_count = 256, .fractal_dimension = q.df, .prefactor = q.kf, .geometric_standard_deviation = sigma};
      const Cluster c = tunable_cluster_aggregation(p, seed++);
      INFO("Df = " << q.df << ", kf = " << q.kf << ", sigma_g = " << sigma);
      REQUIRE(c.size() == 256);
      CHECK(solid_sphere_gyration_radius(c) / law_gyration_radius(c, q.df, q.kf) == Approx(1.0).margin(1e-9));
      CHECK(gyration_radius(c, GyrationConvention::solid_spheres) ==
            Approx(solid_sphere_gyration_radius(c)).epsilon(1e-12));
      CHECK(closest_approach(c) >= 1.0 - 1e-9);
      CHECK(component_count(c) == 1);
      CHECK(norm(centre_of_mass(c)) < 1e-9);
    }
  }
}

TEST_CASE("Every size from 3 to 40 primaries lands on the law") {
  // Sizes up to 32 are grown monomer by monomer (the particle-cluster stage alone), so each is an
  // intermediate aggregate of the others' growth; 33 to 40 add one cluster-cluster join.
  for (std::size_t n = 3; n <= 40; ++n) {
    const Cluster c =
        tunable_cluster_aggregation({.primary_count = n, .fractal_dimension = 1.8, .prefactor = 1.3}, 100 + n);
    INFO("N = " << n);
    CHECK(solid_sphere_gyration_radius(c) / law_gyration_radius(c, 1.8, 1.3) == Approx(1.0).margin(1e-9));
    CHECK(closest_approach(c) >= 1.0 - 1e-9);
    CHECK(component_count(c) == 1);
  }
}

TEST_CASE("The point-mass convention matches cluster_analysis's radius of gyration") {
  const TunableAggregationParameters p{.primary_count = 300,
                                       .fractal_dimension = 2.0,
                                       .prefactor = 1.5,
                                       .geometric_standard_deviation = 1.2,
                                       .gyration_convention = GyrationConvention::point_masses};
  const Cluster c = tunable_cluster_aggregation(p, 5);
  CHECK(radius_of_gyration(c) / law_gyration_radius(c, 2.0, 1.5) == Approx(1.0).margin(1e-9));
  CHECK(closest_approach(c) >= 1.0 - 1e-9);
}

TEST_CASE("A 4096-primary cluster stays exact") {
  const Cluster c = tunable_cluster_aggregation({.primary_count = 4096, .fractal_dimension = 1.8, .prefactor = 1.3}, 2);
  CHECK(solid_sphere_gyration_radius(c) / law_gyration_radius(c, 1.8, 1.3) == Approx(1.0).margin(1e-9));
  const ContactGraph graph = find_contacts(c, 1e-9);
  CHECK(graph.deep_overlap_count == 0);
  CHECK(connected_component_sizes(c.size(), graph.contacts).size() == 1);
}

TEST_CASE("Ensemble fits of Df recover the request") {
  SECTION("monodisperse: exact to round-off") {
    // Every cluster sits on the law, so the fit has no scatter: its standard error is round-off
    // and D_f comes back to ~1e-12.
    for (const Request& q : {Request{1.8, 1.3}, Request{2.6, 1.0}}) {
      std::vector<SizeRadiusSample> samples;
      std::uint64_t seed = 300;
      for (std::size_t n : {32, 64, 128, 256, 512, 1024}) {
        for (int replicate = 0; replicate < 2; ++replicate) {
          const Cluster c =
              tunable_cluster_aggregation({.primary_count = n, .fractal_dimension = q.df, .prefactor = q.kf}, seed++);
          samples.push_back({static_cast<double>(n), solid_sphere_gyration_radius(c)});
        }
      }
      const FractalScalingFit fit = fit_fractal_scaling(samples, 0.5);
      INFO("Df = " << q.df << ": fit " << fit.fractal_dimension << " +- " << fit.fractal_dimension_standard_error
                   << ", kf " << fit.prefactor);
      CHECK(fit.fractal_dimension_standard_error < 1e-9);
      CHECK(fit.fractal_dimension == Approx(q.df).margin(1e-9));
      CHECK(fit.prefactor == Approx(q.kf).epsilon(1e-9));
    }
  }
  SECTION("lognormal: within the fit's standard error") {
    // Each cluster obeys the law with its own geometric mean radius a_own; fitted with the
    // distribution's a = d_g / 2 instead, ln Rg scatters by ln(a_own / a), of variance
    // ln^2 sigma_g / N: heteroscedastic (0.046 at N = 32, 0.008 at 1024), which the fit's pooled
    // residuals underrate at the ends that set the slope. The expected standard error of the
    // least-squares slope 1/Df is sqrt(sum_i w_i^2 var_i), w_i = (x_i - mean x) / S_xx with
    // x = ln N, and that of Df is Df^2 times it (0.012 here). Over 40 base seeds the error in Df
    // had an rms of 0.87 of this and at most 2.3 times it, so the bound is 4 times.
    const double sigma_g = 1.3;
    std::vector<SizeRadiusSample> samples;
    std::vector<double> log_n;
    std::uint64_t seed = 700;
    for (std::size_t n : {32, 64, 128, 256, 512, 1024}) {
      for (int replicate = 0; replicate < 8; ++replicate) {
        const Cluster c = tunable_cluster_aggregation(
            {.primary_count = n, .fractal_dimension = 1.8, .prefactor = 1.3, .geometric_standard_deviation = sigma_g},
            seed++);
        samples.push_back({static_cast<double>(n), solid_sphere_gyration_radius(c)});
        log_n.push_back(std::log(static_cast<double>(n)));
      }
    }
    double mean = 0.0;
    for (double x : log_n) mean += x / static_cast<double>(log_n.size());
    double sxx = 0.0;
    for (double x : log_n) sxx += (x - mean) * (x - mean);
    double slope_variance = 0.0;
    for (double x : log_n) {
      slope_variance += std::pow((x - mean) / sxx, 2) * std::pow(std::log(sigma_g), 2) / std::exp(x);
    }
    const double expected_error = 1.8 * 1.8 * std::sqrt(slope_variance);

    const FractalScalingFit fit = fit_fractal_scaling(samples, 0.5);
    INFO("fit " << fit.fractal_dimension << " +- " << fit.fractal_dimension_standard_error
                << ", expected standard error " << expected_error);
    CHECK(fit.fractal_dimension_standard_error > 0.5 * expected_error);
    CHECK(fit.fractal_dimension_standard_error < 2.0 * expected_error);
    CHECK(std::abs(fit.fractal_dimension - 1.8) < 4.0 * expected_error);
  }
}

TEST_CASE("The internal structure follows the requested Df") {
  // Rg alone is imposed; the mass-radius relation inside one cluster is not, so it checks that the
  // structure is fractal throughout. At N = 1024 (2 d to Rg / 2, about one decade) it reads
  // 1.46-1.53 for Df = 1.6 and 2.26-2.32 for Df = 2.3 over 8 seeds: slightly low, as the local
  // slope falls towards the cluster's edge (see cluster_analysis.hpp).
  const Cluster open =
      tunable_cluster_aggregation({.primary_count = 1024, .fractal_dimension = 1.6, .prefactor = 1.3}, 500);
  const Cluster dense =
      tunable_cluster_aggregation({.primary_count = 1024, .fractal_dimension = 2.3, .prefactor = 1.3}, 500);
  const double d_open = mass_radius_dimension(open);
  const double d_dense = mass_radius_dimension(dense);
  INFO("mass-radius D: " << d_open << " (Df 1.6), " << d_dense << " (Df 2.3)");
  CHECK(d_open == Approx(1.6).margin(0.2));
  CHECK(d_dense == Approx(2.3).margin(0.2));
  CHECK(d_dense - d_open > 0.5);
}

TEST_CASE("Tunable aggregation is reproducible") {
  const TunableAggregationParameters p{
      .primary_count = 500, .fractal_dimension = 2.0, .prefactor = 1.2, .geometric_standard_deviation = 1.2};
  const Cluster a = tunable_cluster_aggregation(p, 42);
  const Cluster b = tunable_cluster_aggregation(p, 42);
  const Cluster other = tunable_cluster_aggregation(p, 43);
  REQUIRE(a.size() == b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    REQUIRE(a.position[i] == b.position[i]);
    REQUIRE(a.radius[i] == b.radius[i]);
  }
  CHECK_FALSE(a.position == other.position);
}

TEST_CASE("Invalid parameters throw std::invalid_argument naming the parameter") {
  const auto message_of = [](const TunableAggregationParameters& p) {
    try {
      tunable_cluster_aggregation(p, 1);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no std::invalid_argument");
  };
  const TunableAggregationParameters ok{.primary_count = 64};
  auto p = ok;
  p.fractal_dimension = 3.5;
  CHECK_THAT(message_of(p), Catch::Contains("fractal_dimension"));
  p = ok;
  p.fractal_dimension = 1.2;
  CHECK_THAT(message_of(p), Catch::Contains("fractal_dimension"));
  p = ok;
  p.primary_count = 0;
  CHECK_THAT(message_of(p), Catch::Contains("primary_count"));
  p = ok;
  p.geometric_standard_deviation = 0.9;
  CHECK_THAT(message_of(p), Catch::Contains("geometric_standard_deviation"));
  p = ok;
  p.prefactor = 0.0;
  CHECK_THAT(message_of(p), Catch::Contains("prefactor"));
  p = ok;
  p.prefactor = std::numeric_limits<double>::quiet_NaN();
  CHECK_THAT(message_of(p), Catch::Contains("prefactor"));
  p = ok;
  p.geometric_mean_diameter = -1.0;
  CHECK_THAT(message_of(p), Catch::Contains("geometric_mean_diameter"));
  p = ok;
  p.particle_cluster_size = 2;
  CHECK_THAT(message_of(p), Catch::Contains("particle_cluster_size"));
}

TEST_CASE("Unreachable requests throw UnreachableFractalParameters naming stage and reason") {
  const auto message_of = [](const TunableAggregationParameters& p) {
    try {
      tunable_cluster_aggregation(p, 1);
    } catch (const UnreachableFractalParameters& e) {
      return std::string(e.what());
    }
    return std::string("no UnreachableFractalParameters");
  };
  SECTION("kf = 0.1 at Df = 2.8: three primaries cannot be that open") {
    const std::string m = message_of({.primary_count = 100, .fractal_dimension = 2.8, .prefactor = 0.1});
    CHECK_THAT(m, Catch::Contains("particle-cluster stage"));
    CHECK_THAT(m, Catch::Contains("too open"));
    CHECK_THAT(m, Catch::Contains("kf must lie in"));
  }
  SECTION("kf = 3 at Df = 2.8: three primaries cannot be that compact") {
    const std::string m = message_of({.primary_count = 100, .fractal_dimension = 2.8, .prefactor = 3.0});
    CHECK_THAT(m, Catch::Contains("particle-cluster stage"));
    CHECK_THAT(m, Catch::Contains("too compact"));
  }
  SECTION("kf = 1 at Df = 1.6: just outside the window") {
    CHECK_THAT(message_of({.primary_count = 100, .fractal_dimension = 1.6, .prefactor = 1.0}),
               Catch::Contains("too open"));
  }
  SECTION("two primaries have a fixed Rg") {
    CHECK_THAT(message_of({.primary_count = 2}), Catch::Contains("fixed Rg"));
  }
  SECTION("wide size distributions at high Df: the aggregates cannot follow the law") {
    const std::string m = message_of(
        {.primary_count = 1024, .fractal_dimension = 2.6, .prefactor = 1.0, .geometric_standard_deviation = 1.6});
    CHECK_THAT(m, Catch::Contains("cannot follow the scaling law"));
    CHECK_THAT(m, Catch::Contains("stage"));
    CHECK_THAT(m, Catch::Contains("Gamma"));
  }
}

TEST_CASE("The three-primary window bounds kf") {
  // Solid spheres: Rg/a from sqrt(4/3 + 3/5) (triangle) to sqrt(8/3 + 3/5) (chain).
  const PrefactorWindow w = three_primary_prefactor_window(1.8, GyrationConvention::solid_spheres, 0.0);
  CHECK(w.lowest == Approx(3.0 / std::pow(std::sqrt(8.0 / 3.0 + 0.6), 1.8)));
  CHECK(w.highest == Approx(3.0 / std::pow(std::sqrt(4.0 / 3.0 + 0.6), 1.8)));
  const PrefactorWindow p = three_primary_prefactor_window(1.8, GyrationConvention::point_masses, 0.0);
  CHECK(p.lowest == Approx(3.0 / std::pow(std::sqrt(8.0 / 3.0), 1.8)));
  CHECK(p.lowest > w.lowest);
}

TEST_CASE("Gamma from FracVAL eq. 6 reproduces the union's Rg") {
  // Two point clusters: masses 2 and 3 at distance 1.7, own Rg 0.4 and 0.9.
  const double m1 = 2.0, m2 = 3.0, rg1 = 0.4, rg2 = 0.9, gamma = 1.7;
  const double rg2_union = (m1 * rg1 * rg1 + m2 * rg2 * rg2 + m1 * m2 / (m1 + m2) * gamma * gamma) / (m1 + m2);
  CHECK(centre_distance_squared(m1, rg1, m2, rg2, std::sqrt(rg2_union)) == Approx(gamma * gamma).epsilon(1e-12));
  CHECK(centre_distance_squared(m1, rg1, m2, rg2, 0.1) < 0.0);
}

TEST_CASE("Free angles avoid every blocked arc") {
  const double pi = std::numbers::pi;
  CHECK_FALSE(free_angle({{0.0, pi}}, 0.5, 1e-9).has_value());
  CHECK(free_angle({}, 0.25, 1e-9).value() == Approx(0.5 * pi));
  // Blocked (-pi/2, pi/2) around 0, wrapping: the free half is [pi/2, 3 pi/2].
  for (double u : {0.0, 0.3, 0.999}) {
    const double a = free_angle({{0.0, 0.5 * pi}}, u, 1e-9).value();
    CHECK(a >= 0.5 * pi);
    CHECK(a <= 1.5 * pi);
  }
  // Two arcs leaving a free set of total length pi / 2.
  CHECK_FALSE(free_angle({{0.0, 0.75 * pi}, {pi, 0.75 * pi}}, 0.5, 1e-9).has_value());
  CHECK(free_angle({{0.0, 0.5 * pi}, {pi, 0.25 * pi}}, 0.0, 1e-9).value() == Approx(0.5 * pi));
}
