#include "orchestrator/export/study_export_data.hpp"

#include <algorithm>
#include <cmath>

#include "orchestrator/export/export_request.hpp"
#include "orchestrator/export/lookup_table.hpp"
#include "orchestrator/study/field_units.hpp"
#include "orchestrator/study/study_axes.hpp"

namespace aerobreak {
namespace {

// Quantities the grid and sections tables have a column of their own for.
const std::vector<std::string> kOwnColumns{"impact_speed", "gamma_over_kn", "primaries", "impact_angle"};

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

std::vector<AxisColumn> extra_axis_columns(const std::vector<GridRowInputs>& inputs) {
  std::vector<const nlohmann::ordered_json*> points;
  for (const auto& row : inputs) points.push_back(&row.grid_point);
  return axis_columns(points, kOwnColumns, !inputs.empty() && inputs.front().scaling.has_value());
}

// Label text of an axis value: a string as it is, anything else as JSON.
std::string label_of(const nlohmann::ordered_json& value) {
  return value.is_string() ? value.get<std::string>() : value.dump();
}

AxisColumn axis_column(const std::string& axis, const std::vector<const nlohmann::ordered_json*>& points) {
  AxisColumn column;
  column.axis = axis;
  column.name = axis_column_name(axis);
  bool numbers = true, booleans = true;
  for (const auto* point : points) {
    const auto found = point->find(axis);
    if (found == point->end()) continue;
    numbers = numbers && found->is_number();
    booleans = booleans && found->is_boolean();
    const std::string label = label_of(*found);
    if (std::find(column.labels.begin(), column.labels.end(), label) == column.labels.end())
      column.labels.push_back(label);
  }
  column.encoding = numbers    ? AxisColumn::Encoding::number
                    : booleans ? AxisColumn::Encoding::boolean
                               : AxisColumn::Encoding::label;
  if (column.encoding != AxisColumn::Encoding::label) column.labels.clear();
  return column;
}

}  // namespace

double AxisColumn::value(const nlohmann::ordered_json& point) const {
  const auto found = point.find(axis);
  if (found == point.end()) return kMissing;
  switch (encoding) {
    case Encoding::number:
      return found->is_number() ? found->get<double>() : kMissing;
    case Encoding::boolean:
      return found->get<bool>() ? 1.0 : 0.0;
    case Encoding::label:
      break;
  }
  const auto label = std::find(labels.begin(), labels.end(), label_of(*found));
  return label == labels.end() ? kMissing : static_cast<double>(label - labels.begin());
}

std::string AxisColumn::unit() const {
  if (encoding != Encoding::number) return "1";
  return exported_axis_unit(axis, physical);
}

std::string AxisColumn::description() const {
  if (encoding == Encoding::boolean) return "study axis " + axis + " (1 = true, 0 = false)";
  if (encoding == Encoding::label)
    return "study axis " + axis + " as the index of its value in metadata axis_labels." + name;
  return "study axis " + axis;
}

std::vector<AxisColumn> axis_columns(const std::vector<const nlohmann::ordered_json*>& points,
                                     const std::vector<std::string>& left_out, bool physical) {
  std::vector<AxisColumn> columns;
  for (const auto* point : points)
    for (const auto& [axis, value] : point->items()) {
      const std::string name = axis_column_name(axis);
      const bool known =
          std::any_of(columns.begin(), columns.end(), [&](const AxisColumn& c) { return c.axis == axis; });
      if (known || std::find(left_out.begin(), left_out.end(), name) != left_out.end()) continue;
      columns.push_back(axis_column(axis, points));
      columns.back().physical = physical;
    }
  return columns;
}

void add_axis_labels(nlohmann::ordered_json& metadata, const std::vector<AxisColumn>& axes) {
  for (const auto& axis : axes)
    if (axis.encoding == AxisColumn::Encoding::label) metadata["axis_labels"][axis.name] = axis.labels;
}

std::string axis_column_name(const std::string& axis) {
  std::string name;
  for (const char c : axis) {
    if (std::isalnum(static_cast<unsigned char>(c)))
      name += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    else if (!name.empty() && name.back() != '_')
      name += '_';
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
  data.extra_axes = extra_axis_columns(data.inputs);
  return data;
}

}  // namespace aerobreak
