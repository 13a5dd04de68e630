// The contact pool keeps one set of constants while all its contacts share them, and switches to
// constants per slot at the first contact that differs, without changing any contact or result.
#include <catch2/catch.hpp>

#include "engine/dem/contact_pool.hpp"
#include "engine/dem/simulation.hpp"
#include "support.hpp"

using namespace aerobreak;

namespace {

ContactState contact_between(std::uint32_t i, std::uint32_t j, double reduced_radius) {
  ContactState s;
  s.i = i;
  s.j = j;
  s.constants.radius = reduced_radius;
  s.constants.mass = 0.5;
  s.constants.break_overlap = 0.01 * reduced_radius;
  s.overlap = 0.001 * (i + 1);
  return s;
}

// Two bonded unit spheres spinning and vibrating near the origin; with `far_pair`, also a sphere
// of diameter 1 and one of diameter 1.4, far off, that meet after about 500 steps and stick.
Particles vibrating_pair(bool far_pair) {
  Particles p;
  p.add({0.0, 0.0, 0.0}, 0.5, testing::unit_density());
  p.add({0.99, 0.0, 0.0}, 0.5, testing::unit_density());
  p.velocity[0] = {-0.01, 0.02, 0.0};
  p.velocity[1] = {0.01, -0.02, 0.005};
  p.angular_velocity[0] = {0.0, 0.0, 0.1};
  p.angular_velocity[1] = {0.05, 0.0, -0.1};
  if (far_pair) {
    p.add({20.0, 0.0, 0.0}, 0.5, testing::unit_density());
    p.add({21.3, 0.0, 0.0}, 0.7, testing::unit_density());
    p.velocity[2] = {0.002, 0.0, 0.0};
    p.velocity[3] = {-0.002, 0.0, 0.0};
  }
  return p;
}

}  // namespace

TEST_CASE("a pool of equal contacts keeps their constants once") {
  ContactPool pool(false);
  const std::int32_t a = pool.open(contact_between(0, 1, 0.25));
  const std::int32_t b = pool.open(contact_between(1, 2, 0.25));
  REQUIRE(pool.shared_constants().has_value());
  CHECK(pool.shared_constants()->radius == 0.25);
  CHECK(pool.constants(a) == pool.constants(b));
  CHECK(pool.break_overlap(b) == 0.0025);
  CHECK(pool.state(b).overlap == 0.002);
}

TEST_CASE("the first contact that differs gives every slot its own constants, kept through renumbering") {
  ContactPool pool(false);
  const std::int32_t a = pool.open(contact_between(0, 1, 0.25));
  const std::int32_t b = pool.open(contact_between(1, 2, 0.25));
  pool.close(a);
  const std::int32_t c = pool.open(contact_between(2, 3, 0.3));  // reuses a's slot
  CHECK(c == a);
  REQUIRE_FALSE(pool.shared_constants().has_value());
  CHECK(pool.reduced_radius(b) == 0.25);
  CHECK(pool.reduced_radius(c) == 0.3);
  CHECK(pool.break_overlap(c) == 0.01 * 0.3);

  std::vector<std::int32_t> references{-1, c, b};  // c first, then b
  pool.renumber(references);
  CHECK(references == std::vector<std::int32_t>{-1, 0, 1});
  CHECK(pool.state(0).i == 2);
  CHECK(pool.state(0).constants.radius == 0.3);
  CHECK(pool.state(1).i == 1);
  CHECK(pool.state(1).constants.radius == 0.25);
  CHECK(pool.state(1).overlap == 0.002);
}

TEST_CASE("switching to constants per slot in mid-run leaves the other contacts' motion bitwise unchanged") {
  // The pair loop reads shared constants as scalars and per-slot constants from columns; both
  // must give the same numbers. The far pair's contact (radii 0.5 and 0.7) makes the switch.
  SimulationSettings settings = testing::bonded();
  settings.time_step = 0.05;
  settings.skin = 0.2;
  Simulation alone(vibrating_pair(false), {testing::unit_material(0.01)}, {}, testing::full_model(), settings);
  Simulation with_far_pair(vibrating_pair(true), {testing::unit_material(0.01)}, {}, testing::full_model(), settings);
  alone.run(1000);
  with_far_pair.run(1000);
  REQUIRE(with_far_pair.contacts().size() == 2);  // the far pair has met
  for (int k = 0; k < 2; ++k) {
    CHECK(alone.particles().position[k] == with_far_pair.particles().position[k]);
    CHECK(alone.particles().velocity[k] == with_far_pair.particles().velocity[k]);
    CHECK(alone.particles().angular_velocity[k] == with_far_pair.particles().angular_velocity[k]);
  }
}
