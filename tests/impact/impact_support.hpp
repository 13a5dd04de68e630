#pragma once
// Builders shared by the impact tests.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

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

}  // namespace aerobreak::testing
