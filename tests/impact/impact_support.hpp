#pragma once
// Builders shared by the impact tests.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "engine/dem/simulation.hpp"

namespace aerobreak::testing {

// A small valid case (reduced units); tests change what they need.
inline nlohmann::ordered_json minimal_case() {
  return nlohmann::ordered_json::parse(R"({
    "cluster": {"generator": {"primaries": 8, "seed": 3}},
    "material": {"gamma_over_kn": 0.01},
    "impact": {"speed": 0.01},
    "run": {"time_limit": 5000}
  })");
}

inline std::filesystem::path source_path(const std::string& relative) {
  return std::filesystem::path(AEROBREAK_SOURCE_DIR) / relative;
}

// The scenes of the fates-fixed rule's tests: primaries of unit mass per unit-diameter sphere,
// JKR with Mindlin friction mu = 0.3 (no damping, rolling or twisting unless a test adds them).
inline constexpr double unit_mass_density = 6.0 / std::numbers::pi;

inline ContactModelSpec jkr_with_friction() {
  ContactModelSpec model;
  model.normal = NormalLaw::jkr;
  model.tangential = true;
  model.friction = 0.3;
  return model;
}

inline Wall flat_wall(bool adhesive) {
  Wall wall;
  wall.adhesive = adhesive;
  return wall;
}

// The wall contacts primary i has now.
inline std::size_t wall_contacts_of(const Simulation& sim, std::uint32_t i) {
  std::size_t n = 0;
  sim.contacts().for_each([&](const ContactState& c) { n += c.with_wall && c.i == i; });
  return n;
}

}  // namespace aerobreak::testing
