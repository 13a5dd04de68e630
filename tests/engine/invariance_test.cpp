// Results do not depend on arbitrary choices: the order of i and j, the orientation of the whole
// system, or how often the neighbour list is rebuilt (contact history survives rebuilds).
#include <catch2/catch.hpp>

#include <cmath>

#include "engine/dem/simulation.hpp"
#include "support.hpp"

using namespace aerobreak;

namespace {

// Rotation by `angle` about the unit axis `u` (Rodrigues).
Vec3 rotate(const Vec3& v, const Vec3& u, double angle) {
  return std::cos(angle) * v + std::sin(angle) * cross(u, v) + (1.0 - std::cos(angle)) * dot(u, v) * u;
}

}  // namespace

TEST_CASE("exchanging i and j gives the same trajectories") {
  Particles ab, ba;
  const Vec3 xa{0.0, 0.0, 0.0}, xb{0.95, 0.2, -0.1}, va{0.05, 0.01, 0.0}, vb{-0.04, 0.0, 0.02};
  const Vec3 wa{0.0, 0.3, 0.1}, wb{0.2, -0.1, 0.0};
  ab.add(xa, 0.5, testing::unit_density());
  ab.add(xb, 0.6, testing::unit_density());
  ba.add(xb, 0.6, testing::unit_density());
  ba.add(xa, 0.5, testing::unit_density());
  ab.velocity = {va, vb};
  ab.angular_velocity = {wa, wb};
  ba.velocity = {vb, va};
  ba.angular_velocity = {wb, wa};
  Simulation first(std::move(ab), {testing::unit_material(0.01)}, {}, testing::full_model());
  Simulation second(std::move(ba), {testing::unit_material(0.01)}, {}, testing::full_model());
  first.run(5000);
  second.run(5000);
  REQUIRE(first.contacts().size() == 1);
  for (int k = 0; k < 2; ++k) {
    CHECK(norm(first.particles().position[k] - second.particles().position[1 - k]) < 1e-12);
    CHECK(norm(first.particles().velocity[k] - second.particles().velocity[1 - k]) < 1e-12);
    CHECK(norm(first.particles().angular_velocity[k] - second.particles().angular_velocity[1 - k]) < 1e-12);
  }
}

TEST_CASE("a rigid rotation of the whole system, wall included, rotates the result") {
  Particles p = testing::relaxed_cluster(40, 21);
  testing::launch_above_floor(p, 0.6, {0.02, -0.01, -0.3});
  const Vec3 axis = Vec3{1.0, 2.0, 3.0} / norm(Vec3{1.0, 2.0, 3.0});
  const double angle = 0.7;
  Particles turned = p;
  for (std::size_t i = 0; i < p.size(); ++i) {
    turned.position[i] = rotate(p.position[i], axis, angle);
    turned.velocity[i] = rotate(p.velocity[i], axis, angle);
  }
  Wall floor;
  Wall tilted{rotate(floor.point, axis, angle), rotate(floor.normal, axis, angle)};
  Simulation straight(std::move(p), {testing::unit_material(0.01)}, {floor}, testing::full_model(), testing::bonded());
  Simulation rotated(std::move(turned), {testing::unit_material(0.01)}, {tilted}, testing::full_model(),
                     testing::bonded());
  straight.run(4000);
  rotated.run(4000);
  REQUIRE(straight.wall_events().made > 0);
  CHECK(straight.contacts().size() == rotated.contacts().size());
  // Round-off differences grow with the contact dynamics; over this short impact they stay small.
  for (std::size_t i = 0; i < straight.particles().size(); ++i) {
    CHECK(norm(rotate(straight.particles().position[i], axis, angle) - rotated.particles().position[i]) < 1e-8);
    CHECK(norm(rotate(straight.particles().velocity[i], axis, angle) - rotated.particles().velocity[i]) < 1e-8);
  }
}

TEST_CASE("contact history survives neighbour-list rebuilds: results do not depend on the skin") {
  Particles p = testing::relaxed_cluster(40, 13);
  for (auto& v : p.velocity) v = {0.1, 0.0, 0.0};  // the whole cluster drifts, forcing rebuilds
  p.angular_velocity[0] = {0.0, 0.0, 2.0};
  SimulationSettings tight = testing::bonded(), loose = testing::bonded();
  tight.skin = 1e-4;
  loose.skin = 50.0;
  tight.time_step = loose.time_step = 0.02;
  Simulation often(p, {testing::unit_material(0.01)}, {}, testing::full_model(), tight);
  Simulation never(p, {testing::unit_material(0.01)}, {}, testing::full_model(), loose);
  often.run(3000);
  never.run(3000);
  REQUIRE(often.neighbor_builds() > 100);
  REQUIRE(never.neighbor_builds() == 1);
  for (std::size_t i = 0; i < often.particles().size(); ++i) {
    CHECK(often.particles().position[i] == never.particles().position[i]);
    CHECK(often.particles().angular_velocity[i] == never.particles().angular_velocity[i]);
  }
}

// A long run integrates each particle as soon as the pair loop has given it its last pair force
// (walls, body forces, kicks and drift in the same pass); a run of one step does each of these in
// a pass of its own. Both must give the same numbers to the last bit, whatever the number of
// particles the pair loop reports complete at once (here several runs of up to 256).
TEST_CASE("one long run equals as many single steps with walls and gravity and Langevin forces") {
  const bool van_der_waals = GENERATE(false, true);
  Particles p = testing::relaxed_cluster(600, 5);
  testing::launch_above_floor(p, 0.52, {0.01, 0.0, -0.2});
  ContactModelSpec model = testing::full_model();
  model.van_der_waals = van_der_waals;
  model.hamaker = {1e-3, 0.01, 0.2};
  SimulationSettings settings = testing::bonded();
  settings.body = testing::gravity_and_bath();
  Simulation whole(p, {testing::unit_material(0.01)}, testing::floor_and_side_walls(), model, settings);
  Simulation stepped(p, {testing::unit_material(0.01)}, testing::floor_and_side_walls(), model, settings);
  const int steps = 1500;
  whole.run(steps);
  for (int s = 0; s < steps; ++s) stepped.step();
  REQUIRE(whole.wall_events().made > 0);
  REQUIRE(whole.pair_events().made > 0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    CHECK(whole.particles().position[i] == stepped.particles().position[i]);
    CHECK(whole.particles().velocity[i] == stepped.particles().velocity[i]);
    CHECK(whole.particles().angular_velocity[i] == stepped.particles().angular_velocity[i]);
  }
  const EnergyBudget a = whole.energy(), b = stepped.energy();
  CHECK(a.dissipation.damping == b.dissipation.damping);
  CHECK(a.dissipation.friction == b.dissipation.friction);
  CHECK(a.dissipation.rolling == b.dissipation.rolling);
  CHECK(a.dissipation.breaking == b.dissipation.breaking);
  CHECK(a.external_work == b.external_work);
  CHECK(a.contact_elastic == b.contact_elastic);
}
