#pragma once
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "engine/core/material.hpp"
#include "orchestrator/export/equivalent_diameters.hpp"

namespace aerobreak {

// kind=correlations is no table: the fitted correlations as code (formats json, fortran, c).
enum class TableKind { grid, fit, sections, correlations };
enum class TableFormat { csv, dat, json, hdf5, melcor, openfoam, fortran, c };

// A material given at export (docs/EXPORT.md, "Units"): SI columns for it, provided its gamma/k_n
// lies in the study's range.
struct ExportMaterial {
  Material material;      // E (Pa), nu, rho (kg/m^3), gamma (J/m^2)
  double diameter = 0.0;  // d, m
};

// What one export asks for: the same parameters as the REST query and the CLI options.
struct ExportRequest {
  TableKind kind = TableKind::grid;
  TableFormat format = TableFormat::csv;
  std::optional<ExportMaterial> material;
  std::optional<double> gamma_over_kn;  // reduced rows of this study value only (not with a material)
  bool interpolate_gamma = false;       // interpolate=gamma_over_kn
  double section_ratio = 2.0;           // sections: ratio of the upper to the lower mass of a section
  std::string quantity = "p_stick";  // openfoam: p_stick | p_bounce | p_break_up | retained_mass_fraction | restitution
  std::string layout =
      "table2d";  // openfoam: table2d (interpolation2DTable) | csv (its data) | dict (Function1 csvFile entries)
  // kind=fit: the grid to evaluate (absent: the fit's own axes) and whether to refuse extrapolation.
  std::vector<double> speeds;
  std::vector<double> sizes;
  // kind=fit: sizes as diameters instead (m when the table has SI, else d; aerodynamic in m only),
  // each turned into N by the relations of docs/EXPORT.md section 2.
  std::vector<double> diameters;
  DiameterType diameter_type = DiameterType::mobility;
  bool strict = false;
  // select=NAME:VALUE[,NAME:VALUE]: only the rows whose input column NAME equals VALUE (a boolean
  // axis as 1 or 0), e.g. one wall of a study that sweeps /wall/adhesive.
  std::vector<std::pair<std::string, double>> select;
};

// A request that cannot be served: the HTTP status it maps to, the parameter at fault, and why.
struct ExportError : std::runtime_error {
  ExportError(int status_code, std::string parameter, const std::string& message)
      : std::runtime_error(message), status(status_code), field(std::move(parameter)) {}
  int status;
  std::string field;
};

// At most this many parameters, of at most this many characters each.
inline constexpr std::size_t kMaxExportParameters = 24;
inline constexpr std::size_t kMaxExportParameterLength = 400;

// Parses name=value parameters (unknown names, bad values and half a material are refused with
// ExportError 400 naming the parameter).
ExportRequest parse_export_request(const std::vector<std::pair<std::string, std::string>>& parameters);

std::string to_string(TableKind kind);
std::string to_string(TableFormat format);

}  // namespace aerobreak
