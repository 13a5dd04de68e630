#include "orchestrator/export/export_request.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

namespace aerobreak {
namespace {

const std::map<std::string, TableKind> kKinds{{"grid", TableKind::grid},
                                              {"fit", TableKind::fit},
                                              {"sections", TableKind::sections},
                                              {"correlations", TableKind::correlations}};
const std::map<std::string, TableFormat> kFormats{
    {"csv", TableFormat::csv},         {"dat", TableFormat::dat},
    {"json", TableFormat::json},       {"hdf5", TableFormat::hdf5},
    {"melcor", TableFormat::melcor},   {"openfoam", TableFormat::openfoam},
    {"fortran", TableFormat::fortran}, {"c", TableFormat::c}};
const std::set<std::string> kQuantities{"p_stick", "p_bounce", "p_break_up", "retained_mass_fraction", "restitution"};
const std::vector<std::string> kMaterialFields{"youngs_modulus", "poisson_ratio", "density", "surface_energy",
                                               "diameter"};

double number(const std::string& name, const std::string& text) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
    throw ExportError(400, name, "parameter '" + name + "' must be a number (got '" + text + "')");
  return value;
}

double positive(const std::string& name, const std::string& text) {
  const double value = number(name, text);
  if (!(value > 0.0)) throw ExportError(400, name, "parameter '" + name + "' must be > 0 (got " + text + ")");
  return value;
}

std::vector<double> positive_list(const std::string& name, const std::string& text) {
  std::vector<double> values;
  std::stringstream items(text);
  for (std::string item; std::getline(items, item, ',');) values.push_back(positive(name, item));
  if (values.empty() || values.size() > 1000)
    throw ExportError(400, name, "parameter '" + name + "' must list 1 to 1000 comma-separated numbers");
  return values;
}

// select=NAME:VALUE[,NAME:VALUE]: column names as the tables write them, values numbers.
std::vector<std::pair<std::string, double>> selections(const std::string& name, const std::string& text) {
  std::vector<std::pair<std::string, double>> selected;
  std::stringstream items(text);
  for (std::string item; std::getline(items, item, ',');) {
    const auto colon = item.find(':');
    const std::string column = item.substr(0, colon);
    if (colon == std::string::npos || column.empty() ||
        column.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_") != std::string::npos)
      throw ExportError(400, name,
                        "parameter 'select' must list NAME:VALUE pairs, NAME a column name (got '" + item + "')");
    selected.emplace_back(column, number(name, item.substr(colon + 1)));
  }
  if (selected.empty()) throw ExportError(400, name, "parameter 'select' must list at least one NAME:VALUE pair");
  return selected;
}

template <typename Value>
Value choice(const std::map<std::string, Value>& choices, const std::string& name, const std::string& text) {
  const auto found = choices.find(text);
  if (found != choices.end()) return found->second;
  std::string allowed;
  for (const auto& [key, value] : choices) allowed += (allowed.empty() ? "" : ", ") + key;
  throw ExportError(400, name, "parameter '" + name + "' must be one of " + allowed + " (got '" + text + "')");
}

bool flag(const std::string& name, const std::string& text) {
  return choice(std::map<std::string, bool>{{"true", true}, {"false", false}, {"1", true}, {"0", false}}, name, text);
}

ExportMaterial material_from(const std::map<std::string, std::string>& given) {
  for (const auto& field : kMaterialFields)
    if (!given.count(field))
      throw ExportError(
          400, field,
          "a material needs all of youngs_modulus, poisson_ratio, density, surface_energy and diameter; '" + field +
              "' is missing");
  ExportMaterial material;
  material.material.youngs_modulus = positive("youngs_modulus", given.at("youngs_modulus"));
  material.material.poisson_ratio = number("poisson_ratio", given.at("poisson_ratio"));
  if (!(material.material.poisson_ratio > -1.0 && material.material.poisson_ratio < 0.5))
    throw ExportError(400, "poisson_ratio", "parameter 'poisson_ratio' must lie in (-1, 0.5)");
  material.material.density = positive("density", given.at("density"));
  material.material.surface_energy = positive("surface_energy", given.at("surface_energy"));
  material.diameter = positive("diameter", given.at("diameter"));
  return material;
}

void apply(ExportRequest& request, const std::string& name, const std::string& value) {
  if (name == "format")
    request.format = choice(kFormats, name, value);
  else if (name == "kind")
    request.kind = choice(kKinds, name, value);
  else if (name == "interpolate")
    request.interpolate_gamma =
        choice(std::map<std::string, bool>{{"gamma_over_kn", true}, {"none", false}}, name, value);
  else if (name == "section_ratio") {
    request.section_ratio = number(name, value);
    if (!(request.section_ratio >= 1.1 && request.section_ratio <= 1000.0))
      throw ExportError(400, name, "parameter 'section_ratio' must lie in [1.1, 1000] (got " + value + ")");
  } else if (name == "quantity") {
    if (!kQuantities.count(value))
      throw ExportError(
          400, name,
          "parameter 'quantity' must be one of p_stick, p_bounce, p_break_up, retained_mass_fraction, restitution");
    request.quantity = value;
  } else if (name == "layout") {
    if (value != "table2d" && value != "csv" && value != "dict")
      throw ExportError(400, name, "parameter 'layout' must be table2d, csv or dict");
    request.layout = value;
  } else if (name == "gamma_over_kn")
    request.gamma_over_kn = positive(name, value);
  else if (name == "speeds")
    request.speeds = positive_list(name, value);
  else if (name == "sizes")
    request.sizes = positive_list(name, value);
  else if (name == "diameters")
    request.diameters = positive_list(name, value);
  else if (name == "diameter_type")
    request.diameter_type = choice(std::map<std::string, DiameterType>{{"mobility", DiameterType::mobility},
                                                                       {"volume", DiameterType::volume},
                                                                       {"aerodynamic", DiameterType::aerodynamic}},
                                   name, value);
  else if (name == "strict")
    request.strict = flag(name, value);
  else if (name == "select")
    request.select = selections(name, value);
  else
    throw ExportError(400, name, "unknown parameter '" + name + "'");
}

}  // namespace

ExportRequest parse_export_request(const std::vector<std::pair<std::string, std::string>>& parameters) {
  if (parameters.size() > kMaxExportParameters)
    throw ExportError(400, "", "at most " + std::to_string(kMaxExportParameters) + " parameters");
  ExportRequest request;
  std::map<std::string, std::string> material;
  std::set<std::string> seen;
  for (const auto& [name, value] : parameters) {
    if (name.size() > 64 || value.size() > kMaxExportParameterLength)
      throw ExportError(400, name.substr(0, 64), "parameter '" + name.substr(0, 64) + "' is too long");
    if (!seen.insert(name).second) throw ExportError(400, name, "parameter '" + name + "' is given twice");
    if (std::find(kMaterialFields.begin(), kMaterialFields.end(), name) != kMaterialFields.end())
      material[name] = value;
    else
      apply(request, name, value);
  }
  if (!material.empty()) request.material = material_from(material);
  const bool code = request.format == TableFormat::fortran || request.format == TableFormat::c;
  if (code && request.kind != TableKind::correlations)
    throw ExportError(400, "format", "formats fortran and c are the code of kind=correlations");
  if (request.kind == TableKind::correlations && !code && request.format != TableFormat::json)
    throw ExportError(
        400, "format",
        "kind=correlations is written as fortran, c or json (got format " + to_string(request.format) + ")");
  if (!request.diameters.empty() && !request.sizes.empty())
    throw ExportError(400, "diameters", "give sizes as primaries (sizes) or as diameters (diameters), not both");
  if (!request.diameters.empty() && request.kind != TableKind::fit)
    throw ExportError(400, "diameters", "diameters are evaluated from the fits: kind=fit");
  if (request.material && request.gamma_over_kn)
    throw ExportError(400, "gamma_over_kn",
                      "give either a material or gamma_over_kn, not both (a material fixes gamma/k_n)");
  return request;
}

std::string to_string(TableKind kind) {
  for (const auto& [name, value] : kKinds)
    if (value == kind) return name;
  return "grid";
}

std::string to_string(TableFormat format) {
  for (const auto& [name, value] : kFormats)
    if (value == format) return name;
  return "csv";
}

}  // namespace aerobreak
