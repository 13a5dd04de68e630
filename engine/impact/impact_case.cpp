#include "engine/impact/impact_case.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "engine/impact/case_hints.hpp"
#include "engine/impact/case_inputs.hpp"
#include "engine/impact/schema_text.hpp"
#include "engine/io/cluster_library.hpp"
#include "engine/io/json_text.hpp"

namespace aerobreak {
namespace {

using Json = nlohmann::ordered_json;

JsonSchema load_schema(std::string_view text, const char* name) {
  try {
    return JsonSchema(Json::parse(text));
  } catch (const std::exception& e) {
    throw std::logic_error(std::string("built-in ") + name + " is not a usable JSON schema: " + e.what());
  }
}

NormalLaw normal_law(const std::string& name) {
  if (name == "dmt") return NormalLaw::dmt;
  if (name == "hertz") return NormalLaw::hertz;
  return NormalLaw::jkr;
}

DampingLaw damping_law(const std::string& name) {
  if (name == "viscoelastic") return DampingLaw::viscoelastic;
  if (name == "tsuji") return DampingLaw::tsuji;
  return DampingLaw::none;
}

ContactModelSpec model_from(const Json& m) {
  ContactModelSpec spec;
  spec.normal = normal_law(m["normal"].get<std::string>());
  spec.separation = m["separation"].get<std::string>() == "force" ? JkrSeparation::force : JkrSeparation::displacement;
  const Json& damping = m["damping"];
  spec.damping = damping_law(damping["law"].get<std::string>());
  spec.dissipative_time = damping["dissipative_time"].get<double>();
  spec.restitution = damping["restitution"].get<double>();
  spec.tangential = m["tangential"].get<bool>();
  spec.friction = m["friction"].get<double>();
  spec.rolling = m["rolling"]["enabled"].get<bool>();
  if (m["rolling"].contains("critical_displacement"))
    spec.critical_rolling = m["rolling"]["critical_displacement"].get<double>();
  spec.twisting = m["twisting"].get<bool>();
  if (m.contains("van_der_waals")) {
    spec.van_der_waals = true;
    spec.hamaker.hamaker = m["van_der_waals"]["hamaker"].get<double>();
    spec.hamaker.min_separation = m["van_der_waals"]["min_separation"].get<double>();
    spec.hamaker.cutoff = m["van_der_waals"]["cutoff"].get<double>();
  }
  return spec;
}

// A cluster library (HDF5) holds named clusters: the case names one, or the library holds one.
// A library that cannot be read (truncated, damaged, not aerobreak's) is a violation naming it.
void check_library_choice(const std::filesystem::path& path, const std::string& name,
                          std::vector<SchemaViolation>& violations) {
  std::vector<std::string> names;
  try {
    names = list_clusters(path);
  } catch (const std::runtime_error& error) {
    violations.push_back({"/cluster/file/path", error.what()});
    return;
  }
  std::string listed;
  for (std::size_t k = 0; k < names.size() && k < 10; ++k) listed += (k == 0 ? "" : ", ") + names[k];
  if (names.size() > 10) listed += ", ...";
  if (name.empty() && names.size() != 1)
    violations.push_back({"/cluster/file/name", "must name the cluster to take: " + path.string() + " holds " +
                                                    std::to_string(names.size()) + " (" + listed + ")"});
  else if (!name.empty() && std::find(names.begin(), names.end(), name) == names.end())
    violations.push_back({"/cluster/file/name", "no cluster '" + name + "' in " + path.string() + " (" + listed + ")"});
}

ClusterSource file_source(const Json& file, const std::filesystem::path& base_directory,
                          std::vector<SchemaViolation>& violations) {
  ClusterSource source;
  source.kind = ClusterSource::Kind::file;
  std::filesystem::path path = file["path"].get<std::string>();
  if (path.is_relative() && !base_directory.empty()) path = base_directory / path;
  source.file = path;
  source.library_name = file.value("name", std::string());
  source.default_radius = file["default_radius"].get<double>();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    violations.push_back({"/cluster/file/path", "no such file: " + path.string()});
  else if (is_hdf5_file(path))
    check_library_choice(path, source.library_name, violations);
  else if (!source.library_name.empty())
    violations.push_back({"/cluster/file/name", "names a cluster of a library, and " + path.string() +
                                                    " is not one (an HDF5 file written by aerobreak cluster)"});
  return source;
}

// The case's cluster: a generator of the registry (its object rewritten as the completed, named
// form, so that an alias gives the same document) or a file.
ClusterSource cluster_source(Json& cluster, const std::filesystem::path& base_directory,
                             std::vector<SchemaViolation>& violations) {
  ClusterSource source;
  if (cluster.contains("generator")) {
    std::vector<GeneratorViolation> wrong;
    source.generator = read_generator_request(cluster["generator"], wrong);
    for (const GeneratorViolation& v : wrong) violations.push_back({"/cluster/generator/" + v.field, v.message});
    if (wrong.empty()) cluster["generator"] = generator_document(source.generator);
  } else {
    source = file_source(cluster["file"], base_directory, violations);
  }
  source.relax = cluster["relax"].get<bool>();
  return source;
}

}  // namespace

const JsonSchema& case_schema() {
  static const JsonSchema schema = load_schema(case_schema_text(), "schemas/case.schema.json");
  return schema;
}

const JsonSchema& result_schema() {
  static const JsonSchema schema = load_schema(result_schema_text(), "schemas/result.schema.json");
  return schema;
}

namespace {

using Violations = std::vector<SchemaViolation>;

// The primaries' material and the wall's, reduced (E in k_n/d, gamma in k_n), the impact speed
// and angle: the primaries' and the impact's as every reader of a case reads them (case_inputs.hpp).
void read_materials(const Json& d, ImpactCase& c) {
  const CaseInputs inputs = read_case_inputs(d);
  c.physical = inputs.physical;
  c.material = inputs.material;
  c.speed = inputs.speed;
  c.angle_degrees = inputs.angle_degrees;

  // Wall material: the primaries' unless given; reduced like them (E in k_n/d, gamma in k_n).
  c.wall_adhesive = d["wall"]["adhesive"].get<bool>();
  c.wall_material = c.material;
  if (d["wall"].contains("material")) {
    const Json& w = d["wall"]["material"];
    if (c.physical) {
      const double kn = c.physical->stiffness();
      c.wall_material.youngs_modulus = w["youngs_modulus"].get<double>() * c.physical->diameter / kn;
      c.wall_material.poisson_ratio = w["poisson_ratio"].get<double>();
      c.wall_material.surface_energy = w["surface_energy"].get<double>() / kn;
    } else {
      c.wall_material.youngs_modulus = c.material.youngs_modulus * w["youngs_modulus_ratio"].get<double>();
      c.wall_material.poisson_ratio = w.value("poisson_ratio", c.material.poisson_ratio);
      c.wall_material.surface_energy = w.value("gamma_over_kn", c.material.surface_energy);
    }
  }
}

// The contact model and the rules on it the schema does not state.
void read_model(const Json& d, ImpactCase& c, Violations& violations) {
  auto violation = [&](const std::string& pointer, const std::string& message) {
    violations.push_back({pointer, message});
  };
  c.model = model_from(d["model"]);
  const bool adhesive_law = c.model.normal != NormalLaw::hertz;
  const std::string energy_field = c.physical ? "/material/surface_energy" : "/material/gamma_over_kn";
  if (adhesive_law && !(c.material.surface_energy > 0.0))
    violation(energy_field, "must be > 0 for the " + d["model"]["normal"].get<std::string>() +
                                " law (use \"normal\": \"hertz\" for spheres without adhesion)");
  if (adhesive_law && c.wall_adhesive && !(c.wall_material.surface_energy + c.material.surface_energy > 0.0))
    violation(c.physical ? "/wall/material/surface_energy" : "/wall/material/gamma_over_kn",
              "must be > 0 for an adhesive wall (or set /wall/adhesive to false)");
  if (c.model.rolling && !adhesive_law)
    violation("/model/rolling/enabled",
              "rolling resistance needs an adhesive normal law (k_r = 4 F_c (a/a0)^(3/2), eq 18)");
  if (c.model.van_der_waals && !(c.model.hamaker.cutoff > c.model.hamaker.min_separation))
    violation("/model/van_der_waals/cutoff", "must exceed /model/van_der_waals/min_separation");
  if (c.model.damping == DampingLaw::viscoelastic && !(c.model.dissipative_time > 0.0))
    violation("/model/damping/dissipative_time", "must be > 0 for visco-elastic damping");
  if (c.model.damping == DampingLaw::tsuji && !(c.model.restitution < 1.0))
    violation("/model/damping/restitution", "must be < 1 for Tsuji damping (1 is no damping: use \"law\": \"none\")");
}

// Why the impact speed cannot reach the wall in time, in the case's own units.
std::string too_slow_message(const Json& d, const ImpactCase& c, double approach_time) {
  std::ostringstream message;
  if (!c.physical) {
    message << "is too small: the cluster would reach the wall after " << approach_time
            << " tau (gap / normal speed), beyond /run/time_limit (" << c.time_limit << " tau)";
    return message.str();
  }
  const double tau = c.physical->time_unit();
  message << "is too small: at " << d["impact"]["speed"].get<double>() << " m/s the cluster would reach the wall after "
          << approach_time * tau << " s (the gap, " << c.gap << " d = " << c.gap * c.physical->diameter
          << " m, over the normal speed), beyond ";
  if (d["run"].contains("time_limit_s"))
    message << "/run/time_limit_s (" << c.time_limit * tau << " s)";
  else
    message << "/run/time_limit (" << c.time_limit << " tau = " << c.time_limit * tau << " s)";
  return message.str();
}

// Time limit, snapshot interval, time step and the settle criterion.
void read_run(const Json& d, ImpactCase& c, Violations& violations) {
  auto violation = [&](const std::string& pointer, const std::string& message) {
    violations.push_back({pointer, message});
  };
  const Json& run = d["run"];
  if (run.contains("time_limit_s")) {
    if (c.physical)
      c.time_limit = run["time_limit_s"].get<double>() / c.physical->time_unit();
    else
      violation("/run/time_limit_s",
                "needs \"units\": \"physical\" (a reduced case has no second; give /run/time_limit in tau)");
  } else {
    c.time_limit = run["time_limit"].get<double>();
  }
  c.snapshot_interval = run.value("snapshot_interval", 0.0);
  c.time_step = run.value("time_step", 0.0);
  c.adaptive_time_step = run["adaptive_time_step"].get<bool>();
  c.steps_per_period = run["steps_per_period"].get<double>();
  c.steps_per_break_overlap = run["steps_per_break_overlap"].get<double>();
  c.settle.quiet_window = run["settle"].value("quiet_window", 0.0);
  c.settle.extent_crossing_fraction = run["settle"].value("extent_crossing_fraction", 0.1);
  c.settle.rest_speed_fraction = run["settle"]["rest_speed_fraction"].get<double>();
  c.settle.stop_when_outcome_fixed = run["settle"].value("stop_when_outcome_fixed", true);
  c.settle.follow_rigid_turn = run["settle"].value("follow_rigid_turn", false);
  if (c.time_step > 0.0 && c.time_limit > 0.0 && c.time_step >= c.time_limit)
    violation("/run/time_step", "must be smaller than /run/time_limit");
  // The cluster starts `gap` above the wall, so its first wall contact comes after gap / v_n
  // (docs/IMPACT.md): a speed too small to reach the wall within time_limit (5e-324 d/tau, say,
  // whose restitution would be noise over nothing) is no impact.
  const double approach_time = c.gap / (c.speed * std::cos(c.angle_degrees * std::numbers::pi / 180.0));
  if (c.time_limit > 0.0 && !(approach_time < c.time_limit))
    violation("/impact/speed", too_slow_message(d, c, approach_time));
}

}  // namespace

namespace {

// A schema-valid, completed case read into reduced units, with the violations of the rules the
// schema does not state (each names the field to change).
ImpactCase read_case(Json document, const std::filesystem::path& base_directory, Violations& violations) {
  ImpactCase c;
  c.document = std::move(document);
  const Json& d = c.document;
  c.name = d.value("name", std::string());
  read_materials(d, c);
  read_model(d, c, violations);
  c.cluster = cluster_source(c.document["cluster"], base_directory, violations);

  const Json& im = d["impact"];
  c.orientation_seed = im["orientation_seed"].get<std::uint64_t>();
  c.gap = im["gap"].get<double>();

  c.thresholds.bounce_share = d["classification"]["largest_fragment_share"].get<double>();
  read_run(d, c, violations);
  return c;
}

// Every problem of a case the schema refuses: its violations and, as far as the rest can be read
// without the fields they name, the rules' violations of the rest. A material in the other unit
// system is reported as that (at /units), followed by the problems of the case in the units it meant.
Violations all_violations(const Json& given, Violations schema_violations,
                          const std::filesystem::path& base_directory) {
  if (const auto hint = units_hint(given)) {
    Json meant = given;
    meant["units"] = hint->meant_units;
    Violations all{hint->violation};
    try {
      parse_impact_case(std::move(meant), base_directory);
    } catch (const CaseError& error) {
      all.insert(all.end(), error.violations().begin(), error.violations().end());
    }
    return all;
  }
  if (given.is_object() && given.value("units", std::string()) == "physical") add_unit_hints(schema_violations);
  if (const auto rest = without_violating_members(case_schema(), given, schema_violations)) {
    Violations rules;
    read_case(*rest, base_directory, rules);
    for (auto& rule : rules)
      if (std::none_of(schema_violations.begin(), schema_violations.end(),
                       [&](const SchemaViolation& v) { return v.pointer == rule.pointer; }))
        schema_violations.push_back(std::move(rule));
  }
  return schema_violations;
}

}  // namespace

ImpactCase parse_impact_case(nlohmann::ordered_json document, const std::filesystem::path& base_directory) {
  const Json given = document;
  Violations violations = case_schema().validate_and_complete(document);
  if (!violations.empty()) throw CaseError(all_violations(given, std::move(violations), base_directory));
  ImpactCase c = read_case(std::move(document), base_directory, violations);
  if (!violations.empty()) throw CaseError(std::move(violations));
  return c;
}

ImpactCase load_impact_case(const std::filesystem::path& path) {
  Json document;
  try {
    document = read_json_file(path, "case file");
  } catch (const InputFileError& e) {
    throw CaseError({{"", std::string(e.what())}});
  }
  return parse_impact_case(std::move(document), path.parent_path());
}

}  // namespace aerobreak
