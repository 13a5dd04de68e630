#pragma once
// Two simulations in the same state to the last bit: what the engine tests of stepping in
// wavefronts, stretches and with the adaptive step compare.
#include <catch2/catch.hpp>

#include "engine/dem/simulation.hpp"

namespace aerobreak::testing {

inline void require_same_state(const Simulation& a, const Simulation& b) {
  REQUIRE(a.particles().size() == b.particles().size());
  REQUIRE(a.step_count() == b.step_count());
  CHECK(a.time() == b.time());
  for (std::size_t i = 0; i < a.particles().size(); ++i) {
    CHECK(a.particles().position[i] == b.particles().position[i]);
    CHECK(a.particles().velocity[i] == b.particles().velocity[i]);
    CHECK(a.particles().angular_velocity[i] == b.particles().angular_velocity[i]);
  }
  const EnergyBudget x = a.energy(), y = b.energy();
  CHECK(x.contact_elastic == y.contact_elastic);
  CHECK(x.dissipation.damping == y.dissipation.damping);
  CHECK(x.dissipation.friction == y.dissipation.friction);
  CHECK(x.dissipation.rolling == y.dissipation.rolling);
  CHECK(x.dissipation.twisting == y.dissipation.twisting);
  CHECK(x.dissipation.breaking == y.dissipation.breaking);
  CHECK(x.external_work == y.external_work);
  CHECK(a.pair_events().made == b.pair_events().made);
  CHECK(a.pair_events().broken == b.pair_events().broken);
  CHECK(a.wall_events().made == b.wall_events().made);
}

}  // namespace aerobreak::testing
