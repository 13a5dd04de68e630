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
  double speed = 0.0;              // d/tau
  double primaries = 0.0;
  double gamma_over_kn = 0.0;
  double poisson_ratio = 0.3;
  double angle = 0.0;              // degrees from head-on
  double fractal_dimension = 0.0;  // the generator's target; NaN when it has none (ballistic)
  std::optional<PhysicalScaling> scaling;  // the case's own material, for a physical study
};

// Everything a table of kind grid or sections is built from, read on the store's reader
// connections (never the writer: an export never waits for, nor blocks, the scheduler).
struct StudyExportData {
  StudyRecord study;
  StudyVersions versions;
  std::vector<GridRowInputs> inputs;                          // per grid point, submission order
  std::map<std::string, GridPointStatistics> statistics;      // by grid key
  std::map<std::string, GridPointFragmentMasses> fragments;   // by grid key (grid points with a determined result)
  std::vector<std::string> extra_axes;                        // axes other than the aliases, numeric ones only
};

GridRowInputs grid_row_inputs(const GridPointCase& point);

// ExportError 404 without such a study, 409 when it has no result yet.
StudyExportData read_study_export_data(Store& store, std::int64_t study_id);

// The column name of an axis given by JSON pointer ("/model/friction" -> "model_friction").
std::string axis_column_name(const std::string& axis);

}  // namespace aerobreak
