#pragma once
#include "tests/support/scratch_directory.hpp"
// Builders and checks shared by the study tests.
#include <catch2/catch.hpp>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "orchestrator/study/study.hpp"

namespace aerobreak::testing {

// A small valid study of 2 x 1 x 1 grid points (reduced units, 8-primary clusters); tests change
// what they need.
inline nlohmann::ordered_json minimal_study() {
  return nlohmann::ordered_json::parse(R"({
    "name": "test study",
    "base": {
      "cluster": {"generator": {}},
      "material": {},
      "run": {"time_limit": 5000}
    },
    "axes": {
      "impact_speed": {"values": [0.01, 0.02]},
      "gamma_over_kn": {"values": [0.001]},
      "primaries": {"values": [8]}
    }
  })");
}

// The violations parse_study reports; fails the test when it accepts the study.
inline std::vector<SchemaViolation> violations_of(const nlohmann::ordered_json& study, const StudyLimits& limits = {},
                                                  const std::filesystem::path& base_directory = {}) {
  try {
    parse_study(study, limits, base_directory);
  } catch (const StudyError& e) {
    return e.violations();
  }
  FAIL("parse_study accepted the study");
  return {};
}

// The first violation at `pointer`; fails the test when there is none.
inline std::string message_at(const std::vector<SchemaViolation>& violations, const std::string& pointer) {
  for (const auto& v : violations)
    if (v.pointer == pointer) return v.message;
  FAIL("no violation at " << pointer << "; got:\n" << describe(violations));
  return {};
}

// Four primaries in a row, touching: a cluster file.
inline const char* kRodXyz = "4\nrod\nC 0 0 0\nC 1 0 0\nC 2 0 0\nC 3 0 0\n";

inline std::filesystem::path source_path(const std::string& relative) {
  return std::filesystem::path(AEROBREAK_SOURCE_DIR) / relative;
}

}  // namespace aerobreak::testing
