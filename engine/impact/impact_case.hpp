#pragma once
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/contact/model_spec.hpp"
#include "engine/core/material.hpp"
#include "engine/core/units.hpp"
#include "engine/impact/cluster_generators.hpp"
#include "engine/impact/json_schema.hpp"
#include "engine/impact/outcome.hpp"

namespace aerobreak {

// Where the cluster of a case comes from.
struct ClusterSource {
  enum class Kind { generated, file };
  Kind kind = Kind::generated;
  GeneratorRequest generator;   // generated (cluster_generators.hpp)
  std::filesystem::path file;   // file (resolved against the case file's directory)
  std::string library_name;     // file: the cluster of a library (HDF5); empty: its only one
  double default_radius = 0.5;  // file (XYZ)
  bool relax = true;
};

// When an impact counts as settled (docs/IMPACT.md, "Settle criterion").
struct SettleCriteria {
  double quiet_window = 0.0;              // tau; 0: automatic
  double extent_crossing_fraction = 0.1;  // automatic window: this share of the time to cross the extent
  double rest_speed_fraction = 0.01;      // of the impact speed
  bool stop_when_outcome_fixed = true;    // the outcome-fixed rule as well as the quiet one
  bool follow_rigid_turn = false;         // that rule follows a fragment's rigid turn (a heuristic)
};

// One impact case, in reduced units (d, m, tau = sqrt(m/k_n)), as schemas/case.schema.json
// describes it. `document` is the case as given, completed with the schema's defaults: it is what
// the result records.
struct ImpactCase {
  nlohmann::ordered_json document;
  std::string name;

  std::optional<PhysicalScaling> physical;  // set for "units": "physical"
  Material material;                        // the primaries, reduced
  Material wall_material;                   // reduced
  bool wall_adhesive = true;
  ContactModelSpec model;
  ClusterSource cluster;

  double speed = 0.0;          // d/tau
  double angle_degrees = 0.0;  // from head-on
  std::uint64_t orientation_seed = 0;
  double gap = 0.01;  // d

  OutcomeThresholds thresholds;  // bounce_share from /classification/largest_fragment_share

  double time_limit = 0.0;         // tau (given as /run/time_limit, or /run/time_limit_s over tau)
  double snapshot_interval = 0.0;  // tau; 0: first and last frames only
  double time_step = 0.0;          // tau; 0: automatic
  bool adaptive_time_step = true;  // automatic: chosen again from the speeds of the moment (MODEL.md 9.2)
  double steps_per_period = 50.0;
  double steps_per_break_overlap = 10.0;
  SettleCriteria settle;
};

// A case that breaks its schema or the physics' rules: every violation, each naming the field by
// its JSON pointer (e.g. "/model/friction: must be >= 0 (got -1)").
class CaseError : public std::invalid_argument {
 public:
  explicit CaseError(std::vector<SchemaViolation> violations)
      : std::invalid_argument(describe(violations)), violations_(std::move(violations)) {}
  const std::vector<SchemaViolation>& violations() const { return violations_; }

 private:
  std::vector<SchemaViolation> violations_;
};

// The case and result schemas (schemas/*.schema.json, compiled in).
const JsonSchema& case_schema();
const JsonSchema& result_schema();

// Validates against schemas/case.schema.json, completes the defaults, checks the rules the schema
// cannot state (an adhesive law needs a surface energy, ...) and converts to reduced units.
// Relative cluster file paths are resolved against `base_directory`. Throws CaseError.
ImpactCase parse_impact_case(nlohmann::ordered_json document, const std::filesystem::path& base_directory = {});
// Reads and parses a case file, bounded as a request body (engine/io/json_text.hpp: a regular file
// of at most 1 MiB, nesting at most 64 deep, numbers a double holds); a file that cannot be read
// that way or is not JSON throws CaseError naming the file and the problem.
ImpactCase load_impact_case(const std::filesystem::path& path);

}  // namespace aerobreak
