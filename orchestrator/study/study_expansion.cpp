#include "orchestrator/study/study_expansion.hpp"

#include <map>
#include <optional>
#include <string>
#include <utility>

#include "engine/impact/cluster_generators.hpp"
#include "engine/impact/impact_case.hpp"
#include "orchestrator/study/canonical_json.hpp"
#include "orchestrator/study/case_hash.hpp"
#include "orchestrator/study/study_axes.hpp"

namespace aerobreak {
namespace {

using Json = nlohmann::ordered_json;

// Beyond this many distinct violations the rest are counted, not listed: a study of many cases
// with a value-dependent error would otherwise answer with one line per case.
constexpr std::size_t kMaxListed = 50;

// Collects the violations of the cases, each distinct (pointer, message) once, with the first case
// that shows it and how many others do.
class CaseViolations {
 public:
  void add(const std::string& pointer, const std::string& message, const std::string& where) {
    const auto [at, inserted] = index_.emplace(std::make_pair(pointer, message), entries_.size());
    if (inserted)
      entries_.push_back({pointer, message, where, 0});
    else
      ++entries_[at->second].others;
  }

  // `cases`: how many were checked, so that a violation of all of them says so.
  std::vector<SchemaViolation> list(std::size_t cases = 0) const {
    std::vector<SchemaViolation> out;
    for (std::size_t k = 0; k < entries_.size() && k < kMaxListed; ++k) {
      const Entry& e = entries_[k];
      std::string context = "in " + e.where;
      if (e.others > 0) context += " and " + std::to_string(e.others) + " other case" + (e.others > 1 ? "s" : "");
      if (cases > 1 && e.others + 1 == cases) context = "in every case";
      out.push_back({e.pointer, e.message + " (" + context + ")"});
    }
    if (entries_.size() > kMaxListed)
      out.push_back(
          {"/axes", std::to_string(entries_.size() - kMaxListed) + " more distinct violations in other cases"});
    return out;
  }

 private:
  struct Entry {
    std::string pointer, message, where;
    std::size_t others;
  };
  std::vector<Entry> entries_;
  std::map<std::pair<std::string, std::string>, std::size_t> index_;
};

// Where a violation of the case field `case_pointer` belongs in the study: the axis that sets the
// field, or else the base.
std::string study_pointer(const Study& study, const std::string& case_pointer) {
  for (const auto& axis : study.axes)
    if (covers(axis.pointer, case_pointer)) return pointer_child("/axes", axis.name);
  if (study.search && covers(study.search->pointer, case_pointer)) return "/search/axis";
  return "/base" + case_pointer;
}

const auto kGenerator = Json::json_pointer("/cluster/generator");

bool swept(const Study& study, const std::string& pointer) {
  for (const auto& axis : study.axes)
    if (covers(axis.pointer, pointer)) return true;
  return false;
}

// The base may hold the parameters of several generators (a generator axis picks one per grid
// point): each case keeps those its generator takes. One that an axis sets stays, and the case's
// validation refuses it for a generator that does not take it.
void keep_own_generator_fields(const Study& study, Json& document) {
  if (!document.contains(kGenerator) || !document[kGenerator].is_object()) return;
  Json& generator = document[kGenerator];
  const Json method = generator.value("method", Json("ballistic"));
  if (!method.is_string() || !find_cluster_generator(method.get<std::string>())) return;
  std::vector<std::string> foreign;
  for (const auto& [field, value] : generator.items())
    if (!generator_takes(method.get<std::string>(), field) && !swept(study, "/cluster/generator/" + field))
      foreign.push_back(field);
  for (const std::string& field : foreign) generator.erase(field);
}

// What identifies the sample (cluster and orientation) of a replicate: the generator's request
// without its seed (completed, an alias resolved), or the cluster file. Every grid point that
// builds the same cluster then meets it in the same orientation, whatever its speed, gamma/k_n or
// model (common random numbers), and one that builds another cluster (another N, generator, D_f,
// k_f, sigma_g) draws an independent cluster and orientation. A file enters by its path (and the
// library cluster it names).
std::string sample_key(const Json& document) {
  if (document.contains(kGenerator) && document[kGenerator].is_object()) {
    try {
      std::vector<GeneratorViolation> reported_later;  // by the case's validation
      Json request = generator_document(read_generator_request(document[kGenerator], reported_later));
      request.erase("seed");
      std::string key = "generator ";
      key += canonical_dump(request);
      return key;
    } catch (const nlohmann::json::exception&) {
      return "invalid generator";  // wrong types: the case's validation says which
    }
  }
  const auto path = Json::json_pointer("/cluster/file/path"), name = Json::json_pointer("/cluster/file/name");
  if (!document.contains(path)) return "no cluster";
  std::string key = "file ";
  key += document[path].dump();
  if (document.contains(name)) {
    key += ' ';
    key += document[name].dump();
  }
  return key;
}

// The replicate's seeds, derived from the study seed, the replicate and the sample key; a seed an
// axis sets stays as the axis set it.
void set_replicate_seeds(const Study& study, int replicate, Json& document) {
  const std::string key = sample_key(document);
  if (document.contains(kGenerator) && document[kGenerator].is_object() && !swept(study, "/cluster/generator/seed"))
    document[kGenerator]["seed"] = replicate_seed(study.seed, "cluster", replicate, key);
  if ((!document.contains("impact") || document["impact"].is_object()) && !swept(study, "/impact/orientation_seed"))
    document["impact"]["orientation_seed"] = replicate_seed(study.seed, "orientation", replicate, key);
}

// The base with the grid point's values and the replicate's seeds set, named after both, labels
// of the base dropped. Returns null when an axis cannot be set (the base has a value in the way).
Json case_document(const Study& study, const Json& grid_point, int replicate, const std::string& where,
                   CaseViolations& violations) {
  Json document = study.document["base"];
  document.erase("name");
  document.erase("description");
  document.erase("$schema");
  std::vector<std::pair<std::string, std::string>> fields;  // (name, pointer) of every value the grid point sets
  for (const auto& axis : study.axes) fields.emplace_back(axis.name, axis.pointer);
  if (study.search) fields.emplace_back(study.search->axis, study.search->pointer);
  for (const auto& [name, pointer] : fields) {
    const std::string where_in_study =
        study.search && name == study.search->axis ? "/search/axis" : pointer_child("/axes", name);
    try {
      document[Json::json_pointer(pointer)] = grid_point[name];
    } catch (const nlohmann::json::exception& e) {
      violations.add(where_in_study, std::string("cannot be set in the case: ") + e.what(), where);
      return nullptr;
    }
  }
  keep_own_generator_fields(study, document);
  set_replicate_seeds(study, replicate, document);

  Json named{{"name", study.name + " | " + grid_label(grid_point) + " | replicate " + std::to_string(replicate)}};
  for (auto& [key, value] : document.items()) named[key] = std::move(value);
  return named;
}

}  // namespace

std::string grid_label(const nlohmann::ordered_json& grid_point) {
  std::string label;
  for (const auto& [name, value] : grid_point.items())
    label += (label.empty() ? "" : " ") + name + "=" + (value.is_string() ? value.get<std::string>() : value.dump());
  return label;
}

namespace {

// Group `point` of the axes (the first axis varies slowest).
Json group_point(const Study& study, std::size_t point) {
  Json grid_point = Json::object();
  std::vector<std::size_t> digits(study.axes.size());
  for (std::size_t i = study.axes.size(), rest = point; i-- > 0;) {
    digits[i] = rest % study.axes[i].values.size();
    rest /= study.axes[i].values.size();
  }
  for (std::size_t i = 0; i < study.axes.size(); ++i) grid_point[study.axes[i].name] = study.axes[i].values[digits[i]];
  return grid_point;
}

// The grid points of one group and the replicate of each: the replicates at the group's point,
// or a search's round-0 values, replicate k at the k-th.
std::vector<std::pair<Json, int>> group_cases(const Study& study, const Json& group) {
  std::vector<std::pair<Json, int>> out;
  if (!study.search) {
    for (int replicate = 0; replicate < study.replicates; ++replicate) out.emplace_back(group, replicate);
    return out;
  }
  const auto candidates = search_candidates(*study.search);
  int replicate = 0;
  for (const auto index : initial_search_indices(*study.search)) {
    Json point = group;
    point[study.search->axis] = candidates[index];
    out.emplace_back(std::move(point), replicate++);
  }
  return out;
}

// The case at a grid point and replicate, validated and hashed; nullopt (the violations noted)
// when it is not a valid case.
std::optional<StudyCase> expand_case(const Study& study, const Json& grid_point, int replicate,
                                     CaseViolations& violations, ClusterFileDigests& digests) {
  const std::string where = "case " + grid_label(grid_point) + ", replicate " + std::to_string(replicate);
  Json document = case_document(study, grid_point, replicate, where, violations);
  if (document.is_null()) return std::nullopt;
  StudyCase c;
  try {
    c.document = parse_impact_case(std::move(document)).document;
  } catch (const CaseError& e) {
    for (const auto& v : e.violations()) violations.add(study_pointer(study, v.pointer), v.message, where);
    return std::nullopt;
  }
  try {
    c.hash = case_hash(c.document, digests);
  } catch (const std::runtime_error& e) {
    violations.add(study_pointer(study, "/cluster/file/path"), e.what(), where);
    return std::nullopt;
  }
  c.grid_point = grid_point;
  c.grid_key = grid_point.dump();
  c.replicate = replicate;
  return c;
}

}  // namespace

StudyExpansion expand_with_violations(const Study& study) {
  StudyExpansion out;
  CaseViolations violations;
  ClusterFileDigests digests;
  std::map<std::string, std::string> first_with_hash;

  out.cases.reserve(study.case_count());
  std::size_t checked = 0;
  for (std::size_t point = 0; point < study.group_count(); ++point) {
    for (const auto& [grid_point, replicate] : group_cases(study, group_point(study, point))) {
      ++checked;
      auto c = expand_case(study, grid_point, replicate, violations, digests);
      if (!c) continue;
      const std::string where = "case " + grid_label(grid_point) + ", replicate " + std::to_string(replicate);
      const auto [first, unique] = first_with_hash.emplace(c->hash, where);
      if (!unique) {
        violations.add("/axes", "gives cases with the same physics (a value repeated, or an axis that changes nothing)",
                       where + " is the same as " + first->second);
        continue;
      }
      out.cases.push_back(std::move(*c));
    }
  }
  out.violations = violations.list(checked);
  return out;
}

StudyCase search_case(const Study& study, const nlohmann::ordered_json& group, double value, int replicate) {
  CaseViolations violations;
  ClusterFileDigests digests;
  Json grid_point = group;
  grid_point[study.search->axis] = value;
  auto c = expand_case(study, grid_point, replicate, violations, digests);
  if (!c) throw StudyError(violations.list());
  return std::move(*c);
}

}  // namespace aerobreak
