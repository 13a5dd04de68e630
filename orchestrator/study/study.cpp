#include "orchestrator/study/study.hpp"

#include <algorithm>
#include <limits>

#include "engine/io/json_text.hpp"
#include "orchestrator/study/canonical_json.hpp"
#include "orchestrator/study/sha256.hpp"
#include "orchestrator/study/study_axes.hpp"
#include "orchestrator/study/study_expansion.hpp"
#include "orchestrator/study/study_schema_text.hpp"

namespace aerobreak {
namespace {

using Json = nlohmann::ordered_json;

constexpr const char* kClusterFile = "/cluster/file";
constexpr const char* kClusterFilePath = "/cluster/file/path";
constexpr const char* kPrimaries = "/cluster/generator/primaries";

bool has_field(const Json& document, const std::string& pointer) {
  return document.contains(Json::json_pointer(pointer));
}

const StudyAxis* axis_setting(const std::vector<StudyAxis>& axes, const std::string& pointer) {
  for (const auto& axis : axes)
    if (covers(axis.pointer, pointer)) return &axis;
  return nullptr;
}

// Relative cluster file paths, in the base and in an axis of paths, become absolute against the
// study file's directory, so that the cases are found wherever the study is run from.
void make_cluster_paths_absolute(Json& document, const std::filesystem::path& directory) {
  auto absolute = [&](Json& path) {
    if (path.is_string() && std::filesystem::path(path.get<std::string>()).is_relative())
      path = (directory / path.get<std::string>()).lexically_normal().string();
  };
  const auto base_path = Json::json_pointer("/base" + std::string(kClusterFilePath));
  if (document.contains(base_path)) absolute(document[base_path]);
  for (auto& [name, spec] : document["axes"].items())
    if (axis_pointer(name) == kClusterFilePath && spec.contains("values"))
      for (auto& value : spec["values"]) absolute(value);
}

// A case field the study sweeps, by an axis or by the search, and where the study names it.
struct SweptField {
  std::string pointer;
  std::string where;  // "/axes/NAME" or "/search/axis"
  std::string label;  // "axis \"NAME\"" or "the search"
};

std::vector<SweptField> swept_fields(const std::vector<StudyAxis>& axes,
                                     const std::optional<BoundarySearchSpec>& search) {
  std::vector<SweptField> fields;
  for (const auto& axis : axes)
    fields.push_back({axis.pointer, pointer_child("/axes", axis.name), "axis \"" + axis.name + "\""});
  if (search && !search->pointer.empty())
    fields.push_back({search->pointer, "/search/axis", "the search (/search/axis)"});
  return fields;
}

bool sets_field(const std::vector<SweptField>& fields, const std::string& pointer) {
  return std::any_of(fields.begin(), fields.end(), [&](const SweptField& f) { return covers(f.pointer, pointer); });
}

// The primaries a study may ask for at most: an axis's values, the search's range, or the base's.
void check_primaries(const Json& base, const std::vector<StudyAxis>& axes,
                     const std::optional<BoundarySearchSpec>& search, const StudyLimits& limits,
                     std::vector<SchemaViolation>& violations) {
  auto too_many = [&](const Json& primaries) {
    return primaries.is_number() && primaries.get<double>() > static_cast<double>(limits.max_primaries);
  };
  const std::string limit_text = "; the limit here is " + std::to_string(limits.max_primaries) + " per case";
  if (const StudyAxis* axis = axis_setting(axes, kPrimaries)) {
    for (const auto& primaries : axis->values)
      if (too_many(primaries)) {
        violations.push_back(
            {pointer_child("/axes", axis->name), "asks for " + primaries.dump() + " primaries" + limit_text});
        break;
      }
  } else if (search && search->pointer == kPrimaries) {
    if (too_many(search->to))
      violations.push_back({"/search/range/to", "asks for " + Json(search->to).dump() + " primaries" + limit_text});
  } else if (has_field(base, kPrimaries) && too_many(base[Json::json_pointer(kPrimaries)])) {
    violations.push_back({"/base" + std::string(kPrimaries),
                          "asks for " + base[Json::json_pointer(kPrimaries)].dump() + " primaries" + limit_text});
  }
}

// The rules on the base: it sets no swept field (an axis's or the search's) and no seed the
// replicates derive, no swept field would create or grow an array (array_growth), it names
// no cluster file where files are refused, and asks for no more primaries than allowed.
void check_base(const Json& base, const std::vector<StudyAxis>& axes, const std::optional<BoundarySearchSpec>& search,
                const StudyLimits& limits, std::vector<SchemaViolation>& violations) {
  const std::vector<SweptField> swept = swept_fields(axes, search);
  for (const auto& field : swept) {
    if (const std::string problem = array_growth(base, field.pointer); !problem.empty()) {
      violations.push_back({field.where, problem});
      continue;
    }
    if (has_field(base, field.pointer))
      violations.push_back({"/base" + field.pointer, "is set by " + field.label + ": leave it out of the base"});
  }
  for (const char* seed : {"/cluster/generator/seed", "/impact/orientation_seed"})
    if (!sets_field(swept, seed) && has_field(base, seed))
      violations.push_back({"/base" + std::string(seed),
                            "is derived for each replicate from /replicates/seed: leave it out of the base (or sweep "
                            "it as an axis to choose it)"});

  if (!limits.allow_cluster_files) {
    const std::string refused =
        "cluster files are not accepted here (the service reads no file a client names): use "
        "/cluster/generator";
    if (has_field(base, kClusterFile)) violations.push_back({"/base" + std::string(kClusterFile), refused});
    for (const auto& field : swept)
      if (covers(field.pointer, kClusterFile) || covers(kClusterFile, field.pointer))
        violations.push_back({field.where, refused});
  }
  check_primaries(base, axes, search, limits, violations);
}

// "16 x 3 x 2 replicates = 96", or "16 x 3 x a budget of 200 = 9600".
std::string count_text(const Study& study) {
  std::string text;
  for (const auto& axis : study.axes) text += std::to_string(axis.values.size()) + " x ";
  if (study.search)
    text += "a budget of " + std::to_string(study.search->budget) + " = ";
  else
    text += std::to_string(study.replicates) + " replicate" + (study.replicates > 1 ? "s" : "") + " = ";
  const std::size_t count = study.case_limit();
  return text + (count == std::numeric_limits<std::size_t>::max() ? "more than " + std::to_string(count)
                                                                  : std::to_string(count));
}

// The search block: its axis is none of the axes, and each of its cases is a replicate of its own.
void read_search(Study& study, const Json& search, std::vector<SchemaViolation>& violations) {
  std::vector<std::string> pointers;
  for (const auto& axis : study.axes) pointers.push_back(axis.pointer);
  study.search = read_search_spec(search, pointers, violations);
  if (study.replicates != 1)
    violations.push_back({"/replicates/count",
                          "must be 1 (the default) in a search: each case of a group draws a "
                          "cluster and orientation of its own"});
}

}  // namespace

const JsonSchema& study_schema() {
  static const JsonSchema schema = [] {
    try {
      return JsonSchema(Json::parse(study_schema_text()));
    } catch (const std::exception& e) {
      throw std::logic_error(std::string("built-in schemas/study.schema.json is not a usable JSON schema: ") +
                             e.what());
    }
  }();
  return schema;
}

namespace {

std::size_t saturating_product(std::size_t a, std::size_t b) {
  constexpr std::size_t kMax = std::numeric_limits<std::size_t>::max();
  return b != 0 && a > kMax / b ? kMax : a * b;
}

}  // namespace

std::size_t Study::group_count() const {
  std::size_t count = 1;
  for (const auto& axis : axes) count = saturating_product(count, axis.values.size());
  return count;
}

std::size_t Study::case_count() const {
  const int per_group = search ? search->initial : replicates;
  return saturating_product(group_count(), per_group > 0 ? static_cast<std::size_t>(per_group) : 0);
}

std::size_t Study::case_limit() const {
  return search ? saturating_product(group_count(), static_cast<std::size_t>(search->budget)) : case_count();
}

namespace {

// The schema's violations and those of the axis names.
std::vector<SchemaViolation> schema_violations(Json& document) {
  std::vector<SchemaViolation> violations = study_schema().validate_and_complete(document);
  if (document.is_object() && document.contains("axes") && document["axes"].is_object())
    check_axis_names(document["axes"], violations, document.contains("search"));
  return violations;
}

// Whether the study can be expanded without the field a violation names: a name, the replicates or
// the execution limits say nothing about the cases' physics, the base, the axes and the search do.
bool outside_the_cases(const SchemaViolation& violation) {
  for (const char* part : {"/base", "/axes", "/search"})
    if (covers(part, violation.pointer)) return false;
  return !violation.pointer.empty();
}

}  // namespace

Study parse_study(nlohmann::ordered_json document, const StudyLimits& limits,
                  const std::filesystem::path& base_directory) {
  std::vector<SchemaViolation> violations = schema_violations(document);
  if (!violations.empty()) {
    // A wrong name or replicate count hides nothing else: the cases are checked as if it were left
    // out, so that one answer lists every problem of the document.
    const bool cases_checkable = std::all_of(violations.begin(), violations.end(), outside_the_cases);
    auto rest = cases_checkable ? without_violating_members(study_schema(), document, violations) : std::nullopt;
    if (!rest || !schema_violations(*rest).empty()) throw StudyError(std::move(violations));
    document = std::move(*rest);
  }
  const std::size_t schema_problems = violations.size();
  const bool searching = document.contains("search");

  if (!base_directory.empty()) make_cluster_paths_absolute(document, base_directory);
  Study study;
  study.name = document["name"].get<std::string>();
  study.description = document.value("description", std::string());
  study.replicates = document["replicates"]["count"].get<int>();
  study.seed = document["replicates"]["seed"].get<std::uint64_t>();
  study.max_attempts = document["execution"]["max_attempts"].get<int>();
  study.case_wall_time = document["execution"]["case_wall_time"].get<double>();
  study.axes = read_axes(document["axes"], violations);
  if (searching) read_search(study, document["search"], violations);
  check_base(document["base"], study.axes, study.search, limits, violations);
  // Counted before anything is expanded: a study of 10^20 cases is refused in microseconds.
  if (study.case_limit() > limits.max_cases)
    violations.push_back({"/axes", "expands to " + count_text(study) + " cases (axis sizes x " +
                                       (searching ? "the search's budget" : "replicates") + "); the limit here is " +
                                       std::to_string(limits.max_cases) + " cases"});
  if (violations.size() > schema_problems) throw StudyError(std::move(violations));

  study.document = std::move(document);
  StudyExpansion expansion = expand_with_violations(study);
  violations.insert(violations.end(), expansion.violations.begin(), expansion.violations.end());
  if (!violations.empty()) throw StudyError(std::move(violations));
  study.cases = std::move(expansion.cases);

  // The name is part of what was submitted; only the reference to the schema file is not.
  Json hashed = study.document;
  hashed.erase("$schema");
  study.hash = sha256_hex("aerobreak-study-v1\n" + canonical_dump(hashed));
  return study;
}

Study load_study(const std::filesystem::path& path, const StudyLimits& limits) {
  Json document;
  try {
    document = read_json_file(path, "study file");
  } catch (const InputFileError& e) {
    throw StudyError({{"", std::string(e.what())}});
  }
  return parse_study(std::move(document), limits, std::filesystem::absolute(path).parent_path());
}

}  // namespace aerobreak
