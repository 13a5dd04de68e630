#pragma once
#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

namespace aerobreak {

// A case stopped because it ran past its wall-clock limit.
class WallTimeExceeded : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct CaseRunOutcome {
  nlohmann::ordered_json result;  // the result document, to_json(ImpactResult)
  std::string data_file;          // the bulk file written; empty when none was asked for
  std::uintmax_t data_file_size = 0;
  std::string data_file_sha256;  // hex, of the file as written
  double seconds = 0.0;          // wall-clock of the whole case: parse, preparation, run, bulk file
};

// Runs one case document (schemas/case.schema.json) in this process: parse_impact_case (relative
// cluster file paths resolve against the working directory; the orchestrator sends absolute
// ones), then run_impact.
//
// wall_time (seconds, 0: none) is enforced cooperatively: the impact's progress callback and the
// set-up stages' log notes check the deadline and throw WallTimeExceeded once it has passed (a
// run that has finished is never thrown away for its last moments). The impact stage is checked about every
// min(1 s, wall_time / 20) plus one chunk of about 1e6 particle-steps; the cluster's relaxation
// runs to its end between two notes, so a case whose relaxation alone takes longer than its wall
// time overruns it by that much.
//
// A non-empty data_file receives the bulk arrays (case_data_file.hpp): written under a name of its
// own ending in ".partial", parent directories created, and renamed when complete; then its size and
// SHA-256 are taken, so that the store can tell later whether the file is still the one written.
//
// Throws CaseError for an invalid document, WallTimeExceeded, DataFileError when the data file
// cannot be written, or what the engine throws.
CaseRunOutcome run_case(const nlohmann::ordered_json& document, double wall_time,
                        const std::filesystem::path& data_file);

}  // namespace aerobreak
