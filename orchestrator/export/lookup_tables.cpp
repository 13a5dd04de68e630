// What an export tabulates: the table of the request's kind, in the request's units, with its
// provenance and validity (docs/EXPORT.md).
#include "orchestrator/export/lookup_tables.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <vector>

#include "engine/core/version.hpp"
#include "orchestrator/export/equivalent_diameters.hpp"

namespace aerobreak {
namespace {

nlohmann::ordered_json provenance(const StudyExportData& data) {
  return {{"study_id", data.study.id},
          {"study_name", data.study.name},
          {"study_hash", data.study.hash},
          {"result_set_version", data.versions.result_set},
          {"aerobreak_version", std::string(version())},
          {"aerobreak_commit", std::string(git_commit())}};
}

nlohmann::ordered_json column_range(const LookupTable& table, const char* name) {
  const auto* column = table.find(name);
  if (!column) return nullptr;
  double low = INFINITY, high = -INFINITY;
  for (const double value : column->values)
    if (!std::isnan(value)) low = std::min(low, value), high = std::max(high, value);
  if (low > high) return nullptr;
  return nlohmann::ordered_json::array({low, high});
}

// The range of one input over the grid points with results: what the fits' data cover.
nlohmann::ordered_json results_range(const StudyExportData& data, double GridRowInputs::*input) {
  double low = INFINITY, high = -INFINITY;
  for (const auto& inputs : data.inputs) {
    const auto found = data.statistics.find(inputs.grid_key);
    if (found == data.statistics.end() || found->second.outcomes.finished() == 0) continue;
    low = std::min(low, inputs.*input), high = std::max(high, inputs.*input);
  }
  if (low > high) return nullptr;
  return nlohmann::ordered_json::array({low, high});
}

// The ranges the results cover: the table's own for grid and sections; for a fit table, whose rows
// may be extrapolated (inside_validity = 0), the study's.
nlohmann::ordered_json validity(const LookupTable& table, const StudyExportData& data) {
  std::size_t flagged = 0, results = 0;
  for (const auto& [key, statistics] : data.statistics) {
    flagged += statistics.outcomes.small_strain_exceeded;
    results += statistics.outcomes.finished();
  }
  const bool fit = table.kind == "fit";
  const auto range = [&](const char* column, double GridRowInputs::*input) {
    return fit ? results_range(data, input) : column_range(table, column);
  };
  nlohmann::ordered_json json{
      {"impact_speed", range("impact_speed", &GridRowInputs::speed)},
      {"gamma_over_kn", range("gamma_over_kn", &GridRowInputs::gamma_over_kn)},
      {"primaries", range("primaries", &GridRowInputs::primaries)},
      {"results", results},
      {"results_outside_small_strain", flagged},
      {"note", fit ? "the ranges the study's results cover; rows outside them are extrapolated "
                     "(inside_validity = 0)"
                   : "tabulated values hold inside these ranges only; nothing is extrapolated"}};
  if (!json["primaries"].is_array()) json.erase("primaries");
  return json;
}

// The validity ranges with the speed's also in m/s when the table has SI columns: each range in the
// unit of the column a reader takes x from (the MELCOR and OpenFOAM adapters read m/s then).
nlohmann::ordered_json with_si_speed(const nlohmann::ordered_json& validity, const PhysicalScaling& scaling) {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (const auto& [key, value] : validity.items()) {
    out[key] = value;
    if (key == "impact_speed" && value.is_array())
      out["impact_speed_m_s"] = {value[0].get<double>() * scaling.speed_unit(),
                                 value[1].get<double>() * scaling.speed_unit()};
  }
  return out;
}

double material_gamma_over_kn(const ExportMaterial& material) {
  return PhysicalScaling{material.material, material.diameter, 1.0}.reduced().surface_energy;
}

nlohmann::ordered_json material_json(const ExportMaterial& material) {
  return {{"youngs_modulus_pa", material.material.youngs_modulus},
          {"poisson_ratio", material.material.poisson_ratio},
          {"density_kg_m3", material.material.density},
          {"surface_energy_j_m2", material.material.surface_energy},
          {"diameter_m", material.diameter},
          {"gamma_over_kn", material_gamma_over_kn(material)}};
}

// The SI of the tables: the export's material, or the study's own (physical study) when every grid
// point has the same; nullopt without.
std::optional<PhysicalScaling> export_scaling(const StudyExportData& data, const ExportRequest& request) {
  if (request.material) return PhysicalScaling{request.material->material, request.material->diameter, 1.0};
  if (data.inputs.empty() || !data.inputs.front().scaling) return std::nullopt;
  const auto& first = *data.inputs.front().scaling;
  for (const auto& inputs : data.inputs)
    if (!inputs.scaling || inputs.scaling->diameter != first.diameter ||
        inputs.scaling->speed_unit() != first.speed_unit())
      return std::nullopt;  // a study sweeping the material: SI only with an export material
  return first;
}

// SI for every row from the export's scaling: nullopt when the rows have none.
std::optional<std::vector<PhysicalScaling>> row_scalings(const LookupTable& table, const StudyExportData& data,
                                                         const ExportRequest& request) {
  const auto scaling = export_scaling(data, request);
  if (!scaling) return std::nullopt;
  return std::vector<PhysicalScaling>(table.rows(), *scaling);
}

// kind=fit with diameters: the request with their N as sizes (docs/EXPORT.md section 2); a diameter
// in m when the table has SI, else in d; an aerodynamic one needs SI.
ExportRequest with_sizes_of_diameters(const ExportRequest& request, const std::optional<PhysicalScaling>& scaling) {
  ExportRequest asked = request;
  if (request.diameters.empty()) return asked;
  if (request.diameter_type == DiameterType::aerodynamic && !scaling)
    throw ExportError(422, "diameter_type",
                      "an aerodynamic diameter needs the primaries' diameter and density: a physical "
                      "study or a material given at export");
  for (const double diameter : request.diameters)
    asked.sizes.push_back(
        request.diameter_type == DiameterType::aerodynamic
            ? primaries_of_diameter(DiameterType::aerodynamic, diameter, scaling->diameter, scaling->material.density)
            : primaries_of_diameter(request.diameter_type, scaling ? diameter / scaling->diameter : diameter));
  return asked;
}

// d/tau in the study's speed unit: a physical study's speeds (and its fits' doses) are in m/s.
double study_speed_unit(const StudyExportData& data) {
  if (data.inputs.empty() || !data.inputs.front().scaling) return 1.0;
  return data.inputs.front().scaling->speed_unit();
}

// A fit table of a study that does not sweep gamma/k_n has no such group axis: its one value, so
// that a material can be checked against it.
void add_constant_gamma(LookupTable& table, const StudyExportData& data) {
  if (table.find("gamma_over_kn") || data.inputs.empty()) return;
  const double gamma = data.inputs.front().gamma_over_kn;
  for (const auto& inputs : data.inputs)
    if (inputs.gamma_over_kn != gamma) return;
  table.add("gamma_over_kn", "1", "adhesion-to-stiffness ratio gamma/k_n (the study's one value)", ColumnRole::input)
      .values.assign(table.rows(), gamma);
}

std::string plain_number(double value) {
  std::ostringstream text;
  text << value;  // the shortest of %g: 1, 1.08, 6.73e-08
  return text.str();
}

// How the table's diameter columns follow from N (docs/EXPORT.md section 2): the relations, their
// constants with sources, and with SI the primaries' diameter and density they were computed with.
nlohmann::ordered_json diameter_metadata(const std::optional<std::vector<PhysicalScaling>>& scalings) {
  nlohmann::ordered_json diameters = {
      {"volume", "d_ve = d N^(1/3)"},
      {"mobility", "d_mob = d (N/k_a)^(1/(2 D_alpha)), k_a = " + plain_number(kProjectedAreaPrefactor) +
                       ", D_alpha = " + plain_number(kProjectedAreaExponent) +
                       ": projected-area scaling (Eggersdorfer et al., J. Aerosol Sci. 46 (2012) 7), equal to the "
                       "mobility diameter for primaries smaller than the gas mean free path (Rogak et al., Aerosol "
                       "Sci. Technol. 18 (1993) 25)"}};
  if (!scalings) return diameters;
  diameters["aerodynamic"] =
      "rho_0 d_ae^2 Cc(d_ae) = rho_p d_ve^3 Cc(d_mob) / d_mob, rho_0 = " + plain_number(kUnitDensity) +
      " kg/m^3, Cc the slip correction in air at 296.15 K and "
      "101.3 kPa, mean free path " +
      plain_number(kAirMeanFreePath) +
      " m (Kim et al., J. Res. NIST 110 (2005) 31; DeCarlo et al., Aerosol Sci. Technol. 38 "
      "(2004) 1185)";
  diameters["primary_diameter_m"] = scalings->front().diameter;
  diameters["primary_density_kg_m3"] = scalings->front().material.density;
  return diameters;
}

}  // namespace

LookupTable study_lookup_table(Store& store, std::int64_t study_id, const ExportRequest& request,
                               const CorrelationSet* fits) {
  if (request.kind == TableKind::fit && !fits) throw ExportError(500, "kind", "kind=fit without the study's fits");
  const auto data = read_study_export_data(store, study_id);
  LookupTable table =
      request.kind == TableKind::grid ? grid_table(data)
      : request.kind == TableKind::sections
          ? sections_table(data, request.section_ratio)
          : fit_table(*fits, with_sizes_of_diameters(request, export_scaling(data, request)), study_speed_unit(data));
  add_constant_gamma(table, data);
  if (!request.select.empty()) table = selected_rows(table, request.select);
  if (request.material)
    table = rows_for_gamma(table, request.material->material, material_gamma_over_kn(*request.material),
                           request.interpolate_gamma);
  else if (request.gamma_over_kn)
    table = rows_for_gamma(table, reduced_material(*request.gamma_over_kn, data.inputs.front().poisson_ratio),
                           *request.gamma_over_kn, request.interpolate_gamma);
  const auto scalings = row_scalings(table, data, request);
  if (scalings) add_si_columns(table, *scalings);
  const auto own_metadata =
      table.metadata.is_object() ? table.metadata : nlohmann::ordered_json::object();  // sections, fit_models
  table.metadata = {{"table", table.kind},
                    {"provenance", provenance(data)},
                    {"units", scalings ? "reduced and SI" : "reduced"},
                    {"reduced_units", "d = primary diameter, m = primary mass, tau = sqrt(m/k_n) (docs/MODEL.md 1.1)"}};
  if (request.material)
    table.metadata["material"] = material_json(*request.material);
  else if (scalings)
    table.metadata["material"] = "the study's own (physical units)";
  if (scalings)
    table.metadata["si_units"] = {{"d_m", scalings->front().diameter},
                                  {"d_per_tau_m_s", scalings->front().speed_unit()}};
  table.metadata["validity"] =
      scalings ? with_si_speed(validity(table, data), scalings->front()) : validity(table, data);
  table.metadata["diameters"] = diameter_metadata(scalings);
  for (const auto& [key, value] : own_metadata.items()) table.metadata[key] = value;
  if (!request.diameters.empty())
    table.metadata["sizes_from"] = std::string(request.diameter_type == DiameterType::mobility ? "mobility"
                                               : request.diameter_type == DiameterType::volume ? "volume-equivalent"
                                                                                               : "aerodynamic") +
                                   " diameters (docs/EXPORT.md section 2), in " + (scalings ? "m" : "d");
  table.metadata["missing_value"] =
      "NaN in HDF5, an empty field in CSV, null in JSON, -1.0e+30 in .dat; left out of MELCOR and OpenFOAM";
  return table;
}

}  // namespace aerobreak
