// Ballistic (BCCA) clusters of lognormal primaries relax to JKR equilibrium (docs/MODEL.md
// 11.1): every contact at the zero-load overlap of its own pair, no net force on any
// primary on the scale of its own pull-off force, at rest, in one piece, nothing broken. The
// expectations are computed here from eqs 1, 2, 4 and 5, not taken from the engine.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <utility>
#include <vector>

#include "engine/cluster/ballistic_aggregation.hpp"
#include "engine/cluster/cluster_contacts.hpp"
#include "engine/contact/normal_jkr.hpp"
#include "engine/dem/impact_placement.hpp"
#include "support.hpp"

using namespace aerobreak;

namespace {

// The material `aerobreak cluster generate` relaxes with by default.
const Material material = testing::unit_material(0.001);
const double work_of_adhesion = 2.0 * material.surface_energy;  // w = 2 gamma, like materials
const double modulus = material.youngs_modulus / (2.0 * (1.0 - material.poisson_ratio * material.poisson_ratio));  // E*

// Contact radius at zero load, eq 4: a0 = (9 pi w R*^2 / (2 E*))^(1/3).
double zero_load_radius(double reduced_radius) {
  return std::cbrt(9.0 * std::numbers::pi * work_of_adhesion * reduced_radius * reduced_radius / (2.0 * modulus));
}

// Overlap at zero load, eq 2 at a = a0: delta0 = a0^2/R* - sqrt(2 pi w a0 / E*).
double zero_load_overlap(double reduced_radius) {
  const double a0 = zero_load_radius(reduced_radius);
  return a0 * a0 / reduced_radius - std::sqrt(2.0 * std::numbers::pi * work_of_adhesion * a0 / modulus);
}

// Pull-off force of two spheres like one of radius r, eq 5 with R* = r/2: F_c = 1.5 pi w r/2.
double own_pull_off_force(double radius) { return 1.5 * std::numbers::pi * work_of_adhesion * 0.5 * radius; }

struct Bond {
  std::size_t i, j;
  double overlap;
  double reduced_radius;
};

// Pairs whose spheres overlap: contacts form only at delta >= 0, and at equilibrium none is in
// tension, so these are all the contacts.
std::vector<Bond> overlapping_pairs(const Particles& p) {
  std::vector<Bond> bonds;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      const double overlap = p.radius[i] + p.radius[j] - norm(p.position[i] - p.position[j]);
      if (overlap > 0.0) bonds.push_back({i, j, overlap, p.radius[i] * p.radius[j] / (p.radius[i] + p.radius[j])});
    }
  return bonds;
}

// Relaxes a BCCA cluster and checks the equilibrium. Measured (N = 64-256, three or four seeds per
// gsd): at most 3.3e4 steps, contacts within 5.4e-7 of delta0; on these nine clusters the net
// contact forces are at most 7.4e-7 F_c,i. The step limit (6x the largest count) makes a
// regression fail in seconds rather than run 5e6 steps.
// Overlap tolerance 1e-5 of delta0: a bond force F moves the overlap by F/k = 0.83 (F/F_c) delta0
// (k = 3.6 F_c R*/a0^2), and a bond inside the tree carries the residual forces of its branch.
void check_relaxes_to_equilibrium(double gsd, std::size_t primaries, std::uint64_t seed) {
  INFO("gsd " << gsd << ", N = " << primaries << ", seed " << seed);
  const Cluster cluster = ballistic_cluster_cluster_aggregation({primaries, 1.0, gsd}, seed);
  RelaxationSettings settings;
  settings.max_steps = 200'000;
  const RelaxationResult r =
      relax_cluster(particles_from_cluster(cluster, material.density), {material}, ContactModelSpec{}, settings);
  REQUIRE(r.converged);
  CHECK(r.contacts_broken == 0);
  CHECK(r.kinetic_per_particle < settings.kinetic_tolerance);
  const Particles& p = r.particles;

  const std::vector<Bond> bonds = overlapping_pairs(p);
  CHECK(bonds.size() == r.contacts);
  CHECK(bonds.size() >= primaries - 1);
  std::vector<std::pair<std::size_t, std::size_t>> edges;
  std::vector<Vec3> net_force(p.size());
  const JkrNormal jkr;
  for (const Bond& b : bonds) {
    const double expected = zero_load_overlap(b.reduced_radius);
    INFO("contact " << b.i << "-" << b.j << ", R* = " << b.reduced_radius);
    CHECK(std::fabs(b.overlap - expected) < 1e-5 * expected);
    edges.push_back({b.i, b.j});
    ContactConstants c =
        sphere_pair_constants(p.radius[b.i], p.mass[b.i], p.radius[b.j], p.mass[b.j], combine(material, material));
    jkr.complete(c);
    const Vec3 push = jkr.respond(b.overlap, c).force * (p.position[b.j] - p.position[b.i]) /
                      norm(p.position[b.j] - p.position[b.i]);  // on j, away from i
    net_force[b.j] += push;
    net_force[b.i] -= push;
  }
  CHECK(connected_component_sizes(p.size(), edges).size() == 1);
  for (std::size_t i = 0; i < p.size(); ++i) {
    INFO("primary " << i << ", d = " << 2.0 * p.radius[i]);
    CHECK(norm(net_force[i]) < settings.force_tolerance * own_pull_off_force(p.radius[i]));
    CHECK(norm(p.velocity[i]) == 0.0);
  }
}

void check_clusters(double gsd) {
  check_relaxes_to_equilibrium(gsd, 64, 1);
  check_relaxes_to_equilibrium(gsd, 128, 2);
  check_relaxes_to_equilibrium(gsd, 256, 3);
}

}  // namespace

TEST_CASE("BCCA clusters of lognormal primaries with gsd 1.3 relax to JKR equilibrium") { check_clusters(1.3); }

TEST_CASE("BCCA clusters of lognormal primaries with gsd 1.6 relax to JKR equilibrium") { check_clusters(1.6); }

TEST_CASE("BCCA clusters of lognormal primaries with gsd 1.8 relax to JKR equilibrium") { check_clusters(1.8); }
