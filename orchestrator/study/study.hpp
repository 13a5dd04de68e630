#pragma once
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/impact/json_schema.hpp"
#include "orchestrator/study/study_search.hpp"

namespace aerobreak {

// What a submitter may ask for. The defaults suit a study file run offline; the REST service
// passes tighter ones.
struct StudyLimits {
  std::size_t max_cases = 100000;
  std::size_t max_primaries = 1000000;  // per case (generator primaries)
  bool allow_cluster_files = true;  // false for studies arriving over HTTP: the server must not read client-named files
};
// The limits of a study a client submits over HTTP (`aerobreak serve`'s defaults, --max-cases and
// --max-primaries; docs/ORCHESTRATOR.md, "Limits").
inline constexpr StudyLimits kServiceStudyLimits{10000, 100000, false};

// One swept case field: its name in the study (an alias such as "impact_speed" or the pointer
// itself), the JSON pointer into the case it sets, and its values in order.
struct StudyAxis {
  std::string name;
  std::string pointer;
  std::vector<nlohmann::ordered_json> values;
};

// One case of a study.
struct StudyCase {
  nlohmann::ordered_json document;    // complete case document, schema defaults filled in
  std::string hash;                   // case_hash(document)
  nlohmann::ordered_json grid_point;  // axis name -> value, in axis order
  std::string grid_key;               // grid_point.dump(): groups the replicates of one grid point
  int replicate = 0;                  // 0-based
};

// A study (schemas/study.schema.json), checked: parse_study has validated every case it expands to.
struct Study {
  nlohmann::ordered_json document;  // as given, completed with the schema's defaults; cluster file paths made absolute
  std::string name, description;
  std::vector<StudyAxis> axes;
  int replicates = 1;
  std::uint64_t seed = 0;
  int max_attempts = 3;
  double case_wall_time = 3600.0;  // seconds
  std::string hash;                // sha256 of the canonical completed study document (identifies a resubmission)
  // An adaptive boundary search (docs/ADAPTIVE.md): its axis is not among `axes`, which then
  // name the groups it searches in (none: one group).
  std::optional<BoundarySearchSpec> search;
  std::size_t group_count() const;  // product of axis sizes (saturating; 1 without axes)
  // Cases at submission: groups x replicates, or groups x the search's initial cases (saturating).
  std::size_t case_count() const;
  // The most cases the study can ever have: case_count(), or groups x the search's budget.
  std::size_t case_limit() const;
  // The cases, expanded and validated once by parse_study: the first axis varies slowest, the
  // replicates (or a search's round-0 values) fastest.
  std::vector<StudyCase> cases;
};

// A study that breaks its schema, its rules or the submitter's limits, or expands to an invalid
// case: every violation, each naming the field by its JSON pointer into the study document.
class StudyError : public std::invalid_argument {
 public:
  explicit StudyError(std::vector<SchemaViolation> violations)
      : std::invalid_argument(describe(violations)), violations_(std::move(violations)) {}
  const std::vector<SchemaViolation>& violations() const { return violations_; }

 private:
  std::vector<SchemaViolation> violations_;
};

// schemas/study.schema.json, compiled in.
const JsonSchema& study_schema();

// Validates a study document against its schema and rules and the limits, checking the number of
// cases before expanding anything, then expands it once (Study::cases) and validates every case
// (parse_impact_case). Relative cluster file paths are made absolute against `base_directory`.
// Throws StudyError.
Study parse_study(nlohmann::ordered_json document, const StudyLimits& limits = {},
                  const std::filesystem::path& base_directory = {});
// Reads and parses a study file (cluster files relative to its directory), bounded as a request
// body (engine/io/json_text.hpp); a file that cannot be read that way or is not JSON throws
// StudyError naming the file and the problem.
Study load_study(const std::filesystem::path& path, const StudyLimits& limits = {});

// The content hash of a completed case document: sha256 over its physics, i.e. the canonical form
// (sorted keys, integral numbers written as integers) without the labels /name, /description and
// /$schema; a cluster file enters by the sha256 of its bytes, not by its path. Same physics, same
// hash, whatever the key order or labels. Throws std::runtime_error for an unreadable cluster file.
std::string case_hash(const nlohmann::ordered_json& completed_case_document);

// The seed of stream `stream` ("cluster", "orientation") for replicate `replicate` of a study
// seeded `study_seed`, for the sample `sample_key` identifies (what builds the cluster: the
// generator's completed request without its seed, or the cluster file; docs/ORCHESTRATOR.md):
// the first 8 bytes of sha256("aerobreak-seed-v2|<seed>|<stream>|<r>|<sample_key>"), big-endian,
// masked to 53 bits so that JSON readers in double precision keep it exact.
std::uint64_t replicate_seed(std::uint64_t study_seed, const std::string& stream, int replicate,
                             const std::string& sample_key);

// A case of an adaptive search: the group's axis values, the search axis at `value`, seeds of
// replicate `replicate` (each case of a group has its own, so that its cases are independent
// samples). Validated and hashed as parse_study does; throws StudyError naming what is wrong.
StudyCase search_case(const Study& study, const nlohmann::ordered_json& group_point, double value, int replicate);

}  // namespace aerobreak
