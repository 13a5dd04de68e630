#pragma once
#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/units.hpp"
#include "orchestrator/store/store.hpp"

namespace aerobreak {

// The inputs of one grid point, read from its first case document (reduced units).
struct GridRowInputs {
  std::string grid_key;
  nlohmann::ordered_json grid_point;
  double speed = 0.0;  // d/tau
  double primaries = 0.0;
  double gamma_over_kn = 0.0;
  double poisson_ratio = 0.3;
  double angle = 0.0;                      // degrees from head-on
  double fractal_dimension = 0.0;          // the generator's target; NaN when it has none (ballistic)
  std::optional<PhysicalScaling> scaling;  // the case's own material, for a physical study
};

// A study axis as a numeric column of a table (docs/EXPORT.md, "Axis columns"), so that rows of
// different conditions never look alike: numbers as they are, booleans as 1 (true) or 0 (false),
// any other axis (text such as a generator name, or mixed values) as the index 0, 1, ... of its
// value in `labels`, the legend written to the metadata (add_axis_labels).
struct AxisColumn {
  enum class Encoding { number, boolean, label };
  std::string axis;  // as the study names it: "/wall/adhesive", "generator"
  std::string name;  // the column: axis_column_name(axis)
  Encoding encoding = Encoding::number;
  std::vector<std::string> labels;  // Encoding::label: the values in the order the grid first uses them
  bool physical = false;            // a physical study: its material's values are SI

  // The axis's value in a grid point or fit group; NaN when the axis is absent.
  double value(const nlohmann::ordered_json& point) const;
  std::string unit() const;
  std::string description() const;
};

// The axes of these grid points (or fit groups), in their order, except those whose column name is
// in `left_out` (quantities with a column of their own); `physical`: of a physical study.
std::vector<AxisColumn> axis_columns(const std::vector<const nlohmann::ordered_json*>& points,
                                     const std::vector<std::string>& left_out, bool physical);

// metadata.axis_labels.NAME = [label of 0, label of 1, ...] for each label-encoded axis.
void add_axis_labels(nlohmann::ordered_json& metadata, const std::vector<AxisColumn>& axes);

// Everything a table of kind grid or sections is built from, read on the store's reader
// connections (never the writer: an export never waits for, nor blocks, the scheduler).
struct StudyExportData {
  StudyRecord study;
  StudyVersions versions;
  std::vector<GridRowInputs> inputs;                         // per grid point, submission order
  std::map<std::string, GridPointStatistics> statistics;     // by grid key
  std::map<std::string, GridPointFragmentMasses> fragments;  // by grid key (grid points with a determined result)
  std::vector<AxisColumn>
      extra_axes;  // the study's axes without a column of their own (not speed, N, gamma/k_n, angle)
};

GridRowInputs grid_row_inputs(const GridPointCase& point);

// ExportError 404 without such a study, 409 when it has no result yet.
StudyExportData read_study_export_data(Store& store, std::int64_t study_id);

// The column name of an axis given by JSON pointer ("/model/friction" -> "model_friction").
std::string axis_column_name(const std::string& axis);

}  // namespace aerobreak
