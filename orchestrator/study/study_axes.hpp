#pragma once
#include <cstddef>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "engine/impact/json_schema.hpp"
#include "orchestrator/study/study.hpp"

namespace aerobreak {

// The axes of a study document: each name resolved to the case field it sets, each list or range
// turned into its values. Violations name their field by JSON pointer into the study document.

// A case field that studies and correlation requests name by a short name. The one table of them
// (study_axes.cpp) serves the axis aliases (axis_pointer, the integer check of read_axes) and the
// correlations' known covariates (orchestrator/app/study_fits.cpp); a field's unit is
// study_axis_unit(pointer), its label and scale describe_axis (field_units.hpp): a covariate enters
// the pooled models as its logarithm where its field is on a log scale (field_log_scale).
struct NamedCaseField {
  std::string_view name;       // the axis alias (axis_alias) or, for a covariate only, its long name
  std::string_view pointer;    // the case field
  bool axis_alias;             // a study may name an axis so (schemas/study.schema.json lists them)
  bool integer;                // a count: an axis of it refuses values that are not integers
  std::string_view covariate;  // its short name as a covariate of the correlations (N, Df); empty: none
};
std::span<const NamedCaseField> named_case_fields();
// The covariates' short names, in the table's order: "gamma_over_kn, N, Df, angle".
std::string known_covariate_names();

// The case field an axis name sets: the alias's pointer, or the name itself when it is a valid
// JSON pointer; empty otherwise.
std::string axis_pointer(const std::string& name);

// The bounds on a JSON pointer a client sends to name a case field (an axis, the search axis):
// at most kMaxPointerLength characters, checked before it is parsed (unescaping "~0" is quadratic
// in the length), and at most kMaxPointerTokens reference tokens (a case is 4 levels deep,
// /model/damping/restitution, and every token past the base's fields creates an object level).
constexpr std::size_t kMaxPointerLength = 256;
constexpr std::size_t kMaxPointerTokens = 8;

// Why `name` names no case field (empty when it names one): neither an alias nor a valid JSON
// pointer into the case, or a pointer past the bounds above. The one check of every axis name.
std::string axis_name_problem(const std::string& name);

// Whether setting the case field `outer` also sets `inner` (the same field, or one inside it).
bool covers(const std::string& outer, const std::string& inner);

// The rules on axis names that the schema cannot state: 1 to 8 axes, each an alias or a valid JSON
// pointer into the case, no label swept, no two axes setting the same field (or one inside the
// other). Needs only "axes" to be an object, so that its answer can join the schema's. A study with
// a search may have no axes (its search then has one group) and at most 7.
void check_axis_names(const nlohmann::ordered_json& axes, std::vector<SchemaViolation>& violations,
                      bool searching = false);

// Why setting `pointer` in `base` would create or grow an array (empty when it would not):
// nlohmann turns a missing "/x/5000000" into an array of 5,000,001 nulls. A case has no arrays
// (schemas/case.schema.json), so a swept field (an axis's, the search's) may index only an
// element the base already has.
std::string array_growth(const nlohmann::ordered_json& base, const std::string& pointer);

// The axes of a schema-valid "axes" object whose names passed check_axis_names, in key order.
// Ranges give exactly `from` first and exactly `to` last; values that are integers are written as
// integers. An integer field (primaries) refuses non-integral values.
std::vector<StudyAxis> read_axes(const nlohmann::ordered_json& axes, std::vector<SchemaViolation>& violations);

}  // namespace aerobreak
