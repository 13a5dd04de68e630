// Diffusion-limited cluster-cluster aggregation grown by the engine (report section 3.2, figure 3):
// one connected, relaxed cluster; reproducible; DLCA fractal scaling; sintering keeps it open.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "engine/cluster/cluster_analysis.hpp"
#include "engine/cluster/cluster_contacts.hpp"
#include "engine/cluster/fractal_scaling_fit.hpp"
#include "engine/growth/diffusion_limited_aggregation.hpp"
#include "engine/growth/growth_history.hpp"

using namespace aerobreak;

namespace {

// At 1 % volume fraction unless said otherwise: the plain engine's cost grows as the box's volume.
DiffusionLimitedParameters parameters(std::size_t n, bool sintering, double volume_fraction = 0.01) {
  DiffusionLimitedParameters p;
  p.primary_count = n;
  p.sintering = sintering;
  p.volume_fraction = volume_fraction;
  return p;
}

// Deepest overlap r_i + r_j - |x_i - x_j| over all pairs (negative if none touch).
double deepest_overlap(const Cluster& c) {
  double deepest = -1e300;
  for (std::size_t i = 0; i < c.size(); ++i)
    for (std::size_t j = i + 1; j < c.size(); ++j)
      deepest = std::max(deepest, c.radius[i] + c.radius[j] - norm(c.position[j] - c.position[i]));
  return deepest;
}

// JKR zero-load overlap a0^2 / (3 R*) of two unit spheres (eqs 2-4), gamma/k_n = 0.01, nu = 0.3:
// a0 = (3 pi gamma / 8)^(1/3) d (eq 4 with eq 7).
double equilibrium_overlap() {
  const double a0 = std::cbrt(3.0 * std::numbers::pi * 0.01 / 8.0);
  return a0 * a0 / (3.0 * 0.25);
}

}  // namespace

TEST_CASE("a grown cluster is one relaxed piece without overlaps beyond the JKR equilibrium") {
  for (bool sintering : {true, false}) {
    const DiffusionLimitedResult r = grow_diffusion_limited(parameters(24, sintering), 5);
    INFO("sintering " << sintering);
    REQUIRE(r.cluster.size() == 24);
    CHECK(r.contacts >= 23);
    CHECK(r.contacts_broken == 0);
    CHECK(r.image_contacts == 0);
    // The bonds of the relaxed cluster sit at the zero-load overlap, 0.069 d (a closed loop may
    // strain one a little); pairs closer than 1.03 d are taken as bonded, which leaves out the
    // near misses a few hundredths of a diameter apart that fractal clusters have.
    const ContactGraph graph = find_contacts(r.cluster, 0.03);
    CHECK(connected_component_sizes(24, graph.contacts) == std::vector<std::size_t>{24});
    // Measured: the deepest overlap equals the zero-load overlap to 1e-4.
    CHECK(deepest_overlap(r.cluster) > 0.95 * equilibrium_overlap());
    CHECK(deepest_overlap(r.cluster) < 1.05 * equilibrium_overlap());
    CHECK(norm(centre_of_mass(r.cluster)) < 1e-9);
  }
}

TEST_CASE("the same seed grows the same cluster, another seed another") {
  const DiffusionLimitedParameters p = parameters(16, true);
  const Cluster a = diffusion_limited_aggregation(p, 11);
  const Cluster b = diffusion_limited_aggregation(p, 11);
  const Cluster c = diffusion_limited_aggregation(p, 12);
  CHECK(a.position == b.position);
  CHECK(a.radius == b.radius);
  CHECK(a.position != c.position);
}

TEST_CASE("the growth stops at the step limit, saying how many clusters remain") {
  DiffusionLimitedParameters p = parameters(40, true);
  p.far_field_motion = DiffusionLimitedParameters::FarField::engine;
  p.max_steps = 20000;
  std::vector<std::size_t> seen;
  const auto record = [&](const DiffusionLimitedProgress& g) { seen.push_back(g.clusters); };
  CHECK_THROWS_WITH(grow_diffusion_limited(p, 1, record),
                    Catch::Contains("clusters remain") && Catch::Contains("after 20000 steps"));
  REQUIRE(seen.size() == 21);  // at steps 0, 1000, ..., 20000
  CHECK(seen.front() == 40);
  CHECK(seen.back() < 40);
  CHECK(seen.back() > 1);
  CHECK(std::is_sorted(seen.rbegin(), seen.rend()));
}

TEST_CASE("the rigid far-field growth stops at its rigid step limit and looks whenever clusters merge") {
  DiffusionLimitedParameters p = parameters(40, true);
  p.max_steps = 200;
  std::vector<std::size_t> seen;
  const auto record = [&](const DiffusionLimitedProgress& g) { seen.push_back(g.clusters); };
  CHECK_THROWS_WITH(grow_diffusion_limited(p, 1, record),
                    Catch::Contains("clusters remain") && Catch::Contains("after 200 rigid steps"));
  REQUIRE(seen.size() >= 2);
  CHECK(seen.front() == 40);
  CHECK(std::adjacent_find(seen.begin(), seen.end()) == seen.end());
}

TEST_CASE("a few primaries in a box smaller than the gap search still grow into one cluster") {
  // At 1 % the box of 2 to 8 primaries is 4.7 to 7.5 d: the rigid far field shortens its search gap
  // to keep one image per pair.
  for (std::size_t n : {2, 3, 8}) {
    INFO(n << " primaries");
    const DiffusionLimitedResult r = grow_diffusion_limited(parameters(n, true), 1);
    CHECK(r.cluster.size() == n);
    CHECK(r.contacts >= n - 1);
  }
}

TEST_CASE("invalid growth parameters are rejected by name") {
  DiffusionLimitedParameters p;
  p.volume_fraction = 0.0;
  CHECK_THROWS_WITH(grow_diffusion_limited(p, 1), Catch::Contains("volume_fraction"));
  p = {};
  p.primary_count = 0;
  CHECK_THROWS_WITH(grow_diffusion_limited(p, 1), Catch::Contains("primary_count"));
  p = {};
  p.persistence_length = 0.0;
  CHECK_THROWS_WITH(grow_diffusion_limited(p, 1), Catch::Contains("persistence_length"));
  p = {};
  p.far_field.release_gap = 0.1;
  CHECK_THROWS_WITH(grow_diffusion_limited(p, 1), Catch::Contains("release_gap"));
  p = {};
  p.primary_count = 1;
  CHECK(diffusion_limited_aggregation(p, 1).size() == 1);
}

TEST_CASE("the DLCA ensemble fractal dimension is the measured 1.64 within what twelve runs justify") {
  // Rg vs N over every cluster of 4..64 primaries that twelve sintered runs of 64 at the default
  // 0.1 % volume fraction formed on their way (GrowthHistory), fitted as N = k_f (Rg/a)^D_f
  // (report figure 2b). Measured over 24 seeds: D_f = 1.642 (k_f = 1.76), per-run standard
  // deviation 0.107, so twelve runs pooled scatter by ~0.107 / sqrt(12) = 0.031 (0.04 allowing
  // for the fit's pooling); the band +-0.15 is ~4 of those. These seeds give 1.633. The value
  // lies below the 1.78 of DLCA without rotation [Meakin 1983; Kolb, Botet & Jullien 1983]: the
  // clusters here turn by rotational diffusion as they approach, which lowers D_f (the same runs
  // with the rigid rotation switched off give 1.89 +- 0.09; Jungblut, Joswig & Eychmueller 2018,
  // arXiv:1810.07109), and it does not depend measurably on the volume fraction from 0.03 % to
  // 1 % (docs/VALIDATION.md section 7). Chain-like (< 1.49) or compact (> 1.79; unsintered
  // growth gives 1.87 +- 0.05 at N = 64) structure falls outside.
  // One history per run: a history names its clusters by lowest member and size, which another
  // run's clusters would share.
  std::vector<SizeRadiusSample> samples;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    GrowthHistory history(4);
    const auto record = [&](const DiffusionLimitedProgress& g) { history.record(*g.components, 0.5); };
    grow_diffusion_limited(parameters(64, true, DiffusionLimitedParameters{}.volume_fraction), seed, record);
    for (const SizeRadiusSample& s : history.samples()) samples.push_back(s);
  }
  const FractalScalingFit fit = fit_fractal_scaling(samples, 0.5);
  INFO("D_f = " << fit.fractal_dimension << " +- " << fit.fractal_dimension_standard_error
                << ", k_f = " << fit.prefactor << ", " << samples.size() << " clusters");
  REQUIRE(samples.size() > 300);
  CHECK(fit.max_primary_count == 64);
  CHECK(fit.fractal_dimension > 1.64 - 0.15);
  CHECK(fit.fractal_dimension < 1.64 + 0.15);
}

TEST_CASE("sintering keeps the clusters more open (report figure 3)") {
  // Without the sintering constraints, bonded primaries roll freely about each other and the
  // clusters fold up; with rolling and twisting resistance they keep the open structure of the
  // collisions that built them. Measured over 8-16 seeds at N = 16: Rg 1.33 +- 0.12 unsintered
  // against 1.88 +- 0.29 sintered (ratio 1.41), and 2.2 against 1.04 contacts per primary. With
  // six seeds each the ratio of the means has a standard error of ~0.10, so 1.10 lies 3 standard
  // errors below the measured ratio (these seeds give 1.84 / 1.49 = 1.24, sintered with the rigid
  // far field, unsintered with the engine throughout, the defaults); the contact counts differ far
  // more (these seeds: 203 against 97).
  double open = 0.0, folded = 0.0;
  std::size_t open_contacts = 0, folded_contacts = 0;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const DiffusionLimitedResult sintered = grow_diffusion_limited(parameters(16, true), seed);
    const DiffusionLimitedResult free = grow_diffusion_limited(parameters(16, false), seed);
    open += radius_of_gyration(sintered.cluster);
    folded += radius_of_gyration(free.cluster);
    open_contacts += sintered.contacts;
    folded_contacts += free.contacts;
  }
  INFO("mean Rg " << open / 6 << " sintered, " << folded / 6 << " unsintered; contacts " << open_contacts << " and "
                  << folded_contacts);
  CHECK(open > 1.10 * folded);
  CHECK(folded_contacts > open_contacts + 6 * 8);
}

namespace {

struct HalfwayReached {};

// Growth time until half the primaries' clusters have merged away (the run is cut there).
double time_to_half(DiffusionLimitedParameters p, std::uint64_t seed) {
  double time = 0.0;
  try {
    grow_diffusion_limited(p, seed, [&](const DiffusionLimitedProgress& g) {
      if (2 * g.clusters > p.primary_count) return;
      time = g.time;
      throw HalfwayReached{};
    });
  } catch (const HalfwayReached&) {
  }
  return time;
}

double mean(const std::vector<double>& x) {
  double sum = 0.0;
  for (double v : x) sum += v;
  return sum / static_cast<double>(x.size());
}

double standard_error(const std::vector<double>& x) {
  const double m = mean(x);
  double sum = 0.0;
  for (double v : x) sum += (v - m) * (v - m);
  return std::sqrt(sum / static_cast<double>(x.size() - 1) / static_cast<double>(x.size()));
}

}  // namespace

TEST_CASE("the rigid far field grows at the engine's rate and to the engine's size") {
  // Sintered, defaults. Time until 32 primaries at 1 % have merged into 16 clusters, 16 seeds per
  // mode, and Rg of the final clusters of 16 primaries, 12 seeds per mode. Measured (16 seeds
  // of N = 32): half time 2698 +- 172 tau rigid against 2842 +- 152 engine; final Rg 2.97 +- 0.09
  // against 2.73 +- 0.11 (the engine's clusters flex thermally while they wait, and close a few
  // more loops: 33.8 against 35.5 contacts). Each mean must agree within 3 combined standard
  // errors.
  DiffusionLimitedParameters rigid = parameters(32, true);
  rigid.far_field_motion = DiffusionLimitedParameters::FarField::rigid;
  DiffusionLimitedParameters engine = rigid;
  engine.far_field_motion = DiffusionLimitedParameters::FarField::engine;
  std::vector<double> rigid_half, engine_half;
  for (std::uint64_t seed = 1; seed <= 16; ++seed) {
    rigid_half.push_back(time_to_half(rigid, seed));
    engine_half.push_back(time_to_half(engine, seed));
  }
  rigid.primary_count = engine.primary_count = 16;
  std::vector<double> rigid_size, engine_size;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    rigid_size.push_back(radius_of_gyration(diffusion_limited_aggregation(rigid, seed)));
    engine_size.push_back(radius_of_gyration(diffusion_limited_aggregation(engine, seed)));
  }
  const auto agree = [](const std::vector<double>& a, const std::vector<double>& b) {
    return std::abs(mean(a) - mean(b)) < 3.0 * std::hypot(standard_error(a), standard_error(b));
  };
  INFO("half time " << mean(rigid_half) << " +- " << standard_error(rigid_half) << " rigid, " << mean(engine_half)
                    << " +- " << standard_error(engine_half) << " engine; Rg(16) " << mean(rigid_size) << " +- "
                    << standard_error(rigid_size) << " rigid, " << mean(engine_size) << " +- "
                    << standard_error(engine_size) << " engine");
  CHECK(agree(rigid_half, engine_half));
  CHECK(agree(rigid_size, engine_size));
}
