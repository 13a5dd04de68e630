#include "orchestrator/export/study_export_data.hpp"

#include <cmath>
#include <set>

#include "orchestrator/export/export_request.hpp"
#include "orchestrator/export/lookup_table.hpp"

namespace aerobreak {
namespace {

const std::set<std::string> kAliases{"impact_speed", "gamma_over_kn", "primaries"};

double value_at(const nlohmann::ordered_json& document, const std::string& pointer, double fallback) {
  const auto json_pointer = nlohmann::ordered_json::json_pointer(pointer);
  if (!document.contains(json_pointer) || !document.at(json_pointer).is_number()) return fallback;
  return document.at(json_pointer).get<double>();
}

PhysicalScaling physical_scaling(const nlohmann::ordered_json& material) {
  PhysicalScaling scaling;
  scaling.material.youngs_modulus = material.at("youngs_modulus").get<double>();
  scaling.material.poisson_ratio = material.value("poisson_ratio", 0.3);
  scaling.material.density = material.at("density").get<double>();
  scaling.material.surface_energy = material.at("surface_energy").get<double>();
  scaling.diameter = material.at("diameter").get<double>();
  return scaling;
}

std::vector<std::string> numeric_extra_axes(const std::vector<GridRowInputs>& inputs) {
  std::vector<std::string> axes;
  if (inputs.empty()) return axes;
  for (const auto& [axis, value] : inputs.front().grid_point.items())
    if (!kAliases.count(axis) && value.is_number()) axes.push_back(axis);
  return axes;
}

}  // namespace

std::string axis_column_name(const std::string& axis) {
  std::string name;
  for (const char c : axis) {
    if (std::isalnum(static_cast<unsigned char>(c))) name += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    else if (!name.empty() && name.back() != '_') name += '_';
  }
  while (!name.empty() && name.back() == '_') name.pop_back();
  return name.empty() ? "axis" : name;
}

GridRowInputs grid_row_inputs(const GridPointCase& point) {
  const auto& document = point.document;
  GridRowInputs inputs;
  inputs.grid_key = point.grid_key;
  inputs.grid_point = point.grid_point;
  inputs.primaries = value_at(document, "/cluster/generator/primaries", kMissing);
  inputs.angle = value_at(document, "/impact/angle", 0.0);
  inputs.fractal_dimension = value_at(document, "/cluster/generator/fractal_dimension", kMissing);
  const double speed = value_at(document, "/impact/speed", kMissing);
  if (document.value("units", std::string("reduced")) == "physical") {
    inputs.scaling = physical_scaling(document.at("material"));
    const Material reduced = inputs.scaling->reduced();
    inputs.gamma_over_kn = reduced.surface_energy;
    inputs.poisson_ratio = reduced.poisson_ratio;
    inputs.speed = inputs.scaling->reduced_speed(speed);
  } else {
    inputs.gamma_over_kn = value_at(document, "/material/gamma_over_kn", kMissing);
    inputs.poisson_ratio = value_at(document, "/material/poisson_ratio", 0.3);
    inputs.speed = speed;
  }
  return inputs;
}

StudyExportData read_study_export_data(Store& store, std::int64_t study_id) {
  StudyExportData data;
  const auto study = store.study(study_id);
  if (!study) throw ExportError(404, "study", "no study " + std::to_string(study_id));
  data.study = *study;
  data.versions = store.study_versions(study_id).value_or(StudyVersions{});
  for (const auto& point : store.grid_point_cases(study_id)) data.inputs.push_back(grid_row_inputs(point));
  std::size_t results = 0;
  for (auto& statistics : store.grid_statistics(study_id)) {
    results += statistics.outcomes.finished();
    data.statistics[statistics.outcomes.grid_key] = std::move(statistics);
  }
  if (results == 0)
    throw ExportError(409, "study", "study " + std::to_string(study_id) + " has no result yet: nothing to tabulate");
  for (auto& masses : store.fragment_masses(study_id)) data.fragments[masses.grid_key] = std::move(masses);
  data.extra_axes = numeric_extra_axes(data.inputs);
  return data;
}

}  // namespace aerobreak
