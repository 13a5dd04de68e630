#pragma once
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "engine/impact/json_schema.hpp"

namespace aerobreak {

// One outcome whose probability the search brackets, and the levels where its crossings are wanted.
struct SearchTarget {
  std::string response;  // stick | bounce | break-up
  std::vector<double> levels;
};

// The "search" block of a study (schemas/study.schema.json, docs/ADAPTIVE.md): one numeric axis
// chosen adaptively, for every group of the other axes' values, until each crossing's 95 %
// interval is narrow enough or the group's case budget is spent.
struct BoundarySearchSpec {
  std::string axis;     // its name in the study: an alias (impact_speed) or a JSON pointer
  std::string pointer;  // the case field it sets
  double from = 0.0;    // the range searched, both ends included
  double to = 0.0;
  bool logarithmic = true;  // the logistic model is in log(value) (scale "log") or in value
  std::vector<SearchTarget> targets;
  double relative_width = 0.0;  // wanted (upper - lower) / estimate; 0: not asked
  double width = 0.0;           // wanted upper - lower in axis units; 0: not asked
  int budget = 200;             // cases per group, all rounds
  int batch = 10;               // cases per group and round after the first
  int initial = 10;             // cases of round 0, spread evenly over the range
  int resolution = 121;         // candidate values over the range (the values cases are placed at)
};

// The spec of a schema-valid "search" object; `axes` are the study's other axis pointers (the
// search axis may not set one of their fields). Violations name fields under /search.
BoundarySearchSpec read_search_spec(const nlohmann::ordered_json& search, const std::vector<std::string>& axis_pointers,
                                    std::vector<SchemaViolation>& violations);

// The candidate values: `resolution` values from `from` to `to`, evenly spaced in the model's
// scale, rounded to 6 significant digits (ends exact), so that cases carry the values people type.
std::vector<double> search_candidates(const BoundarySearchSpec& spec);

// The indices into the candidates of round 0: `initial` values spread evenly over the range, both
// ends included (an index may repeat when initial exceeds the resolution).
std::vector<std::size_t> initial_search_indices(const BoundarySearchSpec& spec);

// The dose of the logistic model at an axis value: log(value) or value.
double search_dose(const BoundarySearchSpec& spec, double value);
double search_value(const BoundarySearchSpec& spec, double dose);

}  // namespace aerobreak
