#pragma once
// What the tests of the service's description share (test_routes): `aerobreak serve` with worker
// jobs of the engine's test double (tests/support/synthetic_worker.cpp, instant results), and
// schemas/openapi.json as the source tree holds it.
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "tests/orchestrator/service_process.hpp"

namespace aerobreak::testing {

// The options of `aerobreak serve` whose worker jobs are the test double: one job of 4 ranks that
// answer at once.
inline std::vector<std::string> synthetic_worker_options() {
  ::setenv("AEROBREAK_SYNTHETIC_RANKS", "4", 1);
  ::setenv("AEROBREAK_SYNTHETIC_DELAY", "0", 1);
  return {"--launcher", "direct", "--ranks", "1", "--worker-program", AEROBREAK_SYNTHETIC_WORKER};
}

inline Json openapi() {
  std::ifstream in(std::filesystem::path(AEROBREAK_SOURCE_DIR) / "schemas" / "openapi.json");
  return Json::parse(in);
}

}  // namespace aerobreak::testing
