// A cluster built at touching distance is relaxed to mechanical equilibrium before use
// (docs/MODEL.md 11.1): contacts at the JKR equilibrium overlap a0^2/(3R*), at rest, intact.
#include <catch2/catch.hpp>

#include <cmath>

#include "engine/contact/normal_jkr.hpp"
#include "support.hpp"

using namespace aerobreak;

TEST_CASE("relaxation brings a touching cluster to JKR equilibrium without breaking it") {
  const Particles touching = testing::random_touching_cluster(50, 17);
  const RelaxationResult r = relax_cluster(touching, {testing::unit_material(0.01)}, ContactModelSpec{});
  REQUIRE(r.converged);
  CHECK(r.contacts_broken == 0);
  CHECK(r.contacts >= touching.size() - 1);  // a random tree of n spheres has n - 1 bonds, loops add more

  // Overlap of every bonded pair against eq 4: delta_eq = a0^2 / (3 R*). Loops in the network can
  // hold a few contacts slightly off equilibrium; in a tree every contact is free to reach it.
  ContactConstants c =
      sphere_pair_constants(0.5, 1.0, 0.5, 1.0, combine(testing::unit_material(0.01), testing::unit_material(0.01)));
  JkrNormal{}.complete(c);
  const double equilibrium = c.equilibrium_radius * c.equilibrium_radius / (3.0 * c.radius);
  std::size_t at_equilibrium = 0;
  for (std::size_t i = 0; i < r.particles.size(); ++i)
    for (std::size_t j = i + 1; j < r.particles.size(); ++j) {
      const double overlap = 1.0 - norm(r.particles.position[i] - r.particles.position[j]);
      if (std::fabs(overlap - equilibrium) < 1e-3 * equilibrium) ++at_equilibrium;
    }
  // Each loop closed by an extra bond may hold up to a few of its contacts off equilibrium.
  const std::size_t loops = r.contacts - (touching.size() - 1);
  CHECK(at_equilibrium <= r.contacts);
  CHECK(at_equilibrium + 4 * loops >= r.contacts);
  for (const auto& v : r.particles.velocity) CHECK(norm(v) == 0.0);
}

TEST_CASE("a relaxed cluster stays put when simulated with the full model") {
  const Particles relaxed = testing::relaxed_cluster(50, 17);
  ContactModelSpec spec;
  spec.rolling = true;
  spec.critical_rolling = 0.01;
  spec.twisting = true;
  Simulation sim(relaxed, {testing::unit_material(0.01)}, {}, spec, testing::bonded());
  const std::size_t contacts = sim.contacts().size();
  sim.run(5000);
  CHECK(sim.contacts().size() == contacts);
  CHECK(sim.pair_events().broken == 0);
  double moved = 0.0;
  for (std::size_t i = 0; i < relaxed.size(); ++i)
    moved = std::max(moved, norm(sim.particles().position[i] - relaxed.position[i]));
  CHECK(moved < 1e-4);
}
