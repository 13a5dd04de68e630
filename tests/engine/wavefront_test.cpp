// Several steps' force passes run together as a wavefront (SimulationSettings::wavefront_depth):
// each pass must give what it gives alone, to the last bit, whatever the depth, in open space
// with walls and in a periodic box, and a wavefront in which a particle leaves the neighbour
// list's skin must be undone and its steps run one at a time.
#include <catch2/catch.hpp>

#include "engine/cluster/ballistic_aggregation.hpp"
#include "engine/dem/impact_placement.hpp"
#include "engine/dem/simulation.hpp"
#include "same_state.hpp"
#include "support.hpp"

using namespace aerobreak;
using aerobreak::testing::require_same_state;

TEST_CASE("a wavefront of any depth gives the steps one at a time to the last bit with walls and body forces") {
  const int depth = GENERATE(2, 5, 16);
  Particles p = testing::relaxed_cluster(600, 5);
  testing::launch_above_floor(p, 0.52, {0.01, 0.0, -0.2});
  const std::vector<Wall> walls = testing::floor_and_side_walls();
  SimulationSettings one = testing::bonded();
  one.body = testing::gravity_and_bath();
  one.wavefront_depth = 1;
  SimulationSettings deep = one;
  deep.wavefront_depth = depth;
  deep.wavefront_min_particles = 0;
  Simulation single(p, {testing::unit_material(0.01)}, walls, testing::full_model(), one);
  SimulationSettings small = deep;
  small.wavefront_min_particles = p.size() + 1;
  Simulation below(p, {testing::unit_material(0.01)}, walls, testing::full_model(), small);
  below.run(100);
  CHECK(below.wavefront_steps() == 0);  // fewer particles than wavefront_min_particles
  Simulation wave(p, {testing::unit_material(0.01)}, walls, testing::full_model(), deep);
  // Several calls: a run's last wavefront may be shorter, and velocities are whole-step between.
  for (int call = 0; call < 3; ++call) {
    single.run(500);
    wave.run(500);
  }
  REQUIRE(single.wavefront_steps() == 0);
  REQUIRE(wave.wavefront_steps() > 1000);  // most steps went through wavefronts
  REQUIRE(wave.wall_events().made > 0);
  REQUIRE(wave.pair_events().made > 0);
  require_same_state(single, wave);
}

TEST_CASE("a wavefront in a periodic box gives the steps one at a time to the last bit") {
  Particles p = testing::relaxed_cluster(200, 9);
  // Across the face x = 0 of the box from the start, drifting and tumbling in a Langevin bath.
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.position[i] += {0.5, 8.0, 8.0};
    p.velocity[i] = {-0.05, 0.02, 0.0};
  }
  SimulationSettings one = testing::bonded();
  one.periodic = PeriodicBox{{16.0, 16.0, 16.0}};
  one.body.langevin = {1e-5, 0.05, 3};
  one.wavefront_depth = 1;
  SimulationSettings deep = one;
  deep.wavefront_depth = 8;
  deep.wavefront_min_particles = 0;
  Simulation single(p, {testing::unit_material(0.01)}, {}, testing::full_model(), one);
  Simulation wave(p, {testing::unit_material(0.01)}, {}, testing::full_model(), deep);
  single.run(3000);
  wave.run(3000);
  REQUIRE(wave.wavefront_steps() > 2000);
  REQUIRE(wave.neighbor_builds() > 1);
  bool wrapped = false;
  for (const ImageCount& image : wave.images()) wrapped = wrapped || image.x != 0;
  REQUIRE(wrapped);
  CHECK(wave.images() == single.images());
  require_same_state(single, wave);
}

TEST_CASE("a wavefront in which a particle leaves the skin is undone and its steps run one at a time") {
  Particles p = testing::relaxed_cluster(40, 13);
  for (auto& v : p.velocity) v = {0.1, 0.0, 0.0};  // 0.002 per step: out of a skin of 0.1 in 25 steps
  p.angular_velocity[0] = {0.0, 0.0, 2.0};
  SimulationSettings one = testing::bonded();
  one.time_step = 0.02;
  one.skin = 0.1;
  one.wavefront_depth = 1;
  SimulationSettings blind = one;
  blind.wavefront_depth = 16;
  blind.wavefront_margin = 0.0;  // every wavefront starts whole: some must be undone
  blind.wavefront_min_particles = 0;
  Simulation single(p, {testing::unit_material(0.01)}, {}, testing::full_model(), one);
  Simulation wave(p, {testing::unit_material(0.01)}, {}, testing::full_model(), blind);
  single.run(1500);
  wave.run(1500);
  REQUIRE(wave.wavefronts_undone() > 0);
  REQUIRE(wave.wavefront_steps() > 0);
  require_same_state(single, wave);
}

// Spheres of many radii: the contacts' constants are kept per slot (ContactPool), and blocks with
// a contact formed or broken since the last rebuild are evaluated on copies.
TEST_CASE("a wavefront over lognormal primaries gives the steps one at a time to the last bit") {
  const Material material = testing::unit_material(0.01);
  const Cluster cluster = ballistic_cluster_cluster_aggregation({300, 1.0, 1.4}, 8);
  Particles p =
      relax_cluster(particles_from_cluster(cluster, material.density), {material}, ContactModelSpec{}).particles;
  testing::launch_above_floor(p, 0.8, {0.02, 0.01, -0.3});
  SimulationSettings one = testing::bonded();
  one.wavefront_depth = 1;
  SimulationSettings deep = one;
  deep.wavefront_depth = 16;
  deep.wavefront_min_particles = 0;
  Simulation single(p, {material}, testing::floor_and_side_walls(), testing::full_model(), one);
  Simulation wave(p, {material}, testing::floor_and_side_walls(), testing::full_model(), deep);
  single.run(1200);
  wave.run(1200);
  REQUIRE(wave.wavefront_steps() > 600);
  REQUIRE(wave.pair_events().made > 0);
  REQUIRE(wave.wall_events().made > 0);
  require_same_state(single, wave);
}
