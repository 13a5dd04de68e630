// The swing-back test of the outcome-fixed rule (engine/impact/fate_rule.hpp, docs/IMPACT.md
// section 4) on a rigid rod of bonded primaries lying parallel to a wall without adhesion, its
// centre rising slowly: turning end over end it swings an end back to the wall; spinning in its
// plane, parallel to the wall, it never comes nearer, although it turns too fast for the bound that
// allows every orientation.
#include <catch2/catch.hpp>

#include <numbers>

#include "engine/core/units.hpp"
#include "engine/dem/simulation.hpp"
#include "engine/impact/fate_rule.hpp"
#include "engine/impact/fragments.hpp"

using namespace aerobreak;

namespace {

const double density = 6.0 / std::numbers::pi;  // unit mass per unit-diameter sphere

// Eleven primaries along x, 0.999 d apart (bonded), centre at height 2 d above the wall, the centre
// rising at `rise`, the rod turning rigidly at `spin`.
Simulation turning_rod(const Vec3& spin, double rise) {
  Particles p;
  for (int k = -5; k <= 5; ++k) p.add({0.999 * k, 0.0, 2.0}, 0.5, density);
  for (std::size_t i = 0; i < p.size(); ++i)
    p.velocity[i] = Vec3{0.0, 0.0, rise} + cross(spin, p.position[i] - Vec3{0.0, 0.0, 2.0});
  for (std::size_t i = 0; i < p.size(); ++i) p.angular_velocity[i] = spin;
  ContactModelSpec model;
  model.normal = NormalLaw::jkr;
  model.tangential = false;
  Wall wall;
  wall.adhesive = false;
  SimulationSettings settings;
  settings.initial_bond_gap = 0.01;
  return Simulation(std::move(p), {reduced_material(0.001, 0.3)}, {wall}, model, settings);
}

}  // namespace

TEST_CASE("a rod rising from the wall swings back if it turns end over end, not if it spins parallel to it") {
  const double rise = 1e-3;  // d/tau; the ends turn at 5e-3 d/tau, five times faster
  const Simulation tumbling = turning_rod({0.0, 1e-3, 0.0}, rise);
  REQUIRE(find_fragments(tumbling).fragments.size() == 1);
  // Turning by pi/2 brings an end 5 d down while the centre rises 1.6 d: it reaches the wall.
  CHECK_THAT(swing_back_reason(tumbling, true), Catch::Contains("swing back"));
  // Spinning about the wall's normal, its ends stay at the height of its centre, which rises.
  CHECK(swing_back_reason(turning_rod({0.0, 0.0, 1e-3}, rise), true).empty());
  // End over end but slowly: by the time its centre has risen past its bounding sphere it has
  // turned by 0.004 rad, an end down by 0.02 d.
  CHECK(swing_back_reason(turning_rod({0.0, 1e-6, 0.0}, rise), true).empty());
  // End over end at a fifth of the rising speed at its ends: the rigid turn keeps its lowest end
  // off the wall, which only following the turn shows; the all-orientation bound refuses it.
  CHECK(swing_back_reason(turning_rod({0.0, 2e-4, 0.0}, rise), true).empty());
  CHECK_THAT(swing_back_reason(turning_rod({0.0, 2e-4, 0.0}, rise), false), Catch::Contains("swing back"));
  // Moving towards the wall, nothing is asked of it (other rules keep such a state open).
  CHECK(swing_back_reason(turning_rod({0.0, 0.0, 1e-3}, -rise), true).empty());
}
