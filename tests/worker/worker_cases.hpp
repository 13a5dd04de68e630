#pragma once
// Case documents and messages shared by the worker tests.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

namespace aerobreak::testing {

// 16 primaries that break up and settle: about 0.05 s of work.
inline nlohmann::ordered_json tiny_case() {
  return nlohmann::ordered_json::parse(R"({
    "cluster": {"generator": {"method": "ballistic", "primaries": 16, "seed": 3}},
    "material": {"gamma_over_kn": 0.001},
    "model": {"damping": {"law": "viscoelastic", "dissipative_time": 0.05}},
    "impact": {"speed": 0.01},
    "run": {"time_limit": 20000}
  })");
}

// The tiny case with a quiet window it never reaches: it runs to its time limit, about 3 s per
// 1e5 tau on one core of the development machine.
inline nlohmann::ordered_json slow_case(double time_limit) {
  nlohmann::ordered_json c = tiny_case();
  c["run"]["time_limit"] = time_limit;
  c["run"]["settle"] = {{"quiet_window", 1e9}};
  return c;
}

inline nlohmann::ordered_json case_message(std::int64_t id, const nlohmann::ordered_json& document,
                                           double wall_time = 0.0, const std::string& data_file = "") {
  return {{"type", "case"},        {"case", id}, {"attempt", 0}, {"document", document}, {"wall_time", wall_time},
          {"data_file", data_file}};
}

inline nlohmann::ordered_json stop_message() { return {{"type", "stop"}}; }

}  // namespace aerobreak::testing
