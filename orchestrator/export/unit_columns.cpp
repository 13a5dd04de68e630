// Units of docs/EXPORT.md: rows of one gamma/k_n (matched or interpolated), rows of one selected
// condition (select=NAME:VALUE) and SI columns.
#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "engine/core/units.hpp"
#include "orchestrator/export/equivalent_diameters.hpp"
#include "orchestrator/export/lookup_tables.hpp"

namespace aerobreak {
namespace {

constexpr double kGammaTolerance = 1e-3;  // relative: a study value this close is the material's

bool same_gamma(double a, double b) { return std::abs(a - b) <= kGammaTolerance * std::max(a, b); }

// The input columns other than gamma/k_n: the rows of one condition share them.
std::vector<double> condition(const LookupTable& table, std::size_t row) {
  std::vector<double> key;
  for (const auto& column : table.columns)
    if ((column.role == ColumnRole::input || column.role == ColumnRole::speed) && column.name != "gamma_over_kn")
      key.push_back(key_value(column.values[row]));
  return key;
}

LookupTable empty_like(const LookupTable& table) {
  LookupTable selected = table;
  for (auto& column : selected.columns) column.values.clear();
  return selected;
}

// Linear interpolation of every column between rows `low` and `high` with weight w of high.
void append_interpolated(LookupTable& out, const LookupTable& table, std::size_t low, std::size_t high, double w) {
  for (std::size_t c = 0; c < table.columns.size(); ++c)
    out.columns[c].values.push_back((1.0 - w) * table.columns[c].values[low] + w * table.columns[c].values[high]);
}

// lambda (eq 19) again from the interpolated gamma/k_n: it is not linear in ln(gamma/k_n).
void recompute_lambda(LookupTable& table, double poisson_ratio) {
  auto* lambda = table.find("lambda");
  const auto* speed = table.find("impact_speed");
  if (!lambda || !speed) return;
  for (std::size_t row = 0; row < table.rows(); ++row)
    lambda->values[row] = adhesion_energy_ratio(
        reduced_material(table.find("gamma_over_kn")->values[row], poisson_ratio), 1.0, speed->values[row]);
}

LookupTable interpolated_rows(const LookupTable& table, double target, const std::vector<double>& gammas) {
  LookupTable out = empty_like(table);
  const auto upper = std::upper_bound(gammas.begin(), gammas.end(), target);
  const double g_low = *(upper - 1), g_high = *upper;
  const double w = std::log(target / g_low) / std::log(g_high / g_low);
  const auto& gamma = table.find("gamma_over_kn")->values;
  std::map<std::vector<double>, std::size_t> low_rows;
  for (std::size_t row = 0; row < table.rows(); ++row)
    if (same_gamma(gamma[row], g_low)) low_rows[condition(table, row)] = row;
  for (std::size_t row = 0; row < table.rows(); ++row) {
    if (!same_gamma(gamma[row], g_high)) continue;
    const auto low = low_rows.find(condition(table, row));
    if (low != low_rows.end()) append_interpolated(out, table, low->second, row, w);
  }
  // The rows stand for the material's gamma/k_n itself, not for a linear mean of the two values.
  auto& gamma_out = out.find("gamma_over_kn")->values;
  std::fill(gamma_out.begin(), gamma_out.end(), target);
  auto& interpolated =
      out.add("interpolated", "1", "1: interpolated in ln(gamma/k_n) between two study values", ColumnRole::output);
  interpolated.values.assign(out.rows(), 1.0);
  return out;
}

}  // namespace

LookupTable rows_for_gamma(const LookupTable& table, const Material& material, double target, bool interpolate) {
  const auto* gamma_column = table.find("gamma_over_kn");
  if (!gamma_column)
    throw ExportError(422, "surface_energy", "this table has no gamma/k_n to check a material against");
  std::set<double> distinct(gamma_column->values.begin(), gamma_column->values.end());
  const std::vector<double> gammas(distinct.begin(), distinct.end());
  char range[160];
  std::snprintf(range, sizeof range,
                "the material's gamma/k_n = 3 gamma (1 - nu^2) / (E d) = %.4g; the study covers %.4g to %.4g", target,
                gammas.front(), gammas.back());
  if (target < gammas.front() * (1.0 - kGammaTolerance) || target > gammas.back() * (1.0 + kGammaTolerance))
    throw ExportError(422, "surface_energy",
                      std::string(range) + ": a material outside the study's range is refused, not extrapolated");
  LookupTable selected = empty_like(table);
  for (std::size_t row = 0; row < table.rows(); ++row)
    if (same_gamma(gamma_column->values[row], target))
      for (std::size_t c = 0; c < table.columns.size(); ++c)
        selected.columns[c].values.push_back(table.columns[c].values[row]);
  if (selected.rows() > 0) return selected;
  if (!interpolate)
    throw ExportError(
        422, "surface_energy",
        std::string(range) + " but has no value within 0.1 % of it; add interpolate=gamma_over_kn to interpolate");
  auto out = interpolated_rows(table, target, gammas);
  recompute_lambda(out, material.poisson_ratio);
  if (out.rows() == 0)
    throw ExportError(422, "interpolate", std::string(range) + ": no condition has both bracketing values");
  return out;
}

LookupTable selected_rows(const LookupTable& table, const std::vector<std::pair<std::string, double>>& select) {
  std::vector<const TableColumn*> columns;
  for (const auto& [name, value] : select) {
    const auto* column = table.find(name);
    if (column && column->role == ColumnRole::input) {
      columns.push_back(column);
      continue;
    }
    std::string inputs;
    for (const auto& input : table.columns)
      if (input.role == ColumnRole::input) inputs += (inputs.empty() ? "" : ", ") + input.name;
    throw ExportError(422, "select",
                      "this table (kind " + table.kind + ") has no input column '" + name + "'; its inputs: " + inputs);
  }
  LookupTable selected = empty_like(table);
  for (std::size_t row = 0; row < table.rows(); ++row) {
    bool keep = true;
    for (std::size_t i = 0; i < select.size(); ++i) keep = keep && columns[i]->values[row] == select[i].second;
    if (keep)
      for (std::size_t c = 0; c < table.columns.size(); ++c)
        selected.columns[c].values.push_back(table.columns[c].values[row]);
  }
  if (selected.rows() == 0) throw ExportError(422, "select", "no row of this table has every value of select");
  return selected;
}

namespace {

// d_ae_m beside d_mob_m: the aerodynamic diameter of the row's N (from its mobility diameter).
TableColumn aerodynamic_column(const TableColumn& mobility, const std::vector<PhysicalScaling>& scalings) {
  TableColumn column{"d_ae_m",
                     "m",
                     "aerodynamic diameter: the unit-density sphere settling as fast, in air at 296 K and "
                     "101.3 kPa (docs/EXPORT.md section 2)",
                     ColumnRole::derived,
                     {}};
  for (std::size_t row = 0; row < mobility.values.size(); ++row) {
    const double primaries = primaries_of_diameter(DiameterType::mobility, mobility.values[row]);
    column.values.push_back(std::isnan(primaries) ? kMissing
                                                  : aerodynamic_diameter(primaries, scalings[row].diameter,
                                                                         scalings[row].material.density));
  }
  return column;
}

}  // namespace

void add_si_columns(LookupTable& table, const std::vector<PhysicalScaling>& scalings) {
  std::vector<TableColumn> columns;
  for (auto& column : table.columns) {
    columns.push_back(column);
    const bool speed = column.unit == "d/tau", length = column.unit == "d";
    if (!speed && !length) continue;
    TableColumn si{column.name + (speed ? "_m_s" : "_m"),
                   speed ? "m/s" : "m",
                   column.description + ", SI",
                   column.role == ColumnRole::output ? ColumnRole::output : ColumnRole::derived,
                   {}};
    for (std::size_t row = 0; row < column.values.size(); ++row)
      si.values.push_back(column.values[row] * (speed ? scalings[row].speed_unit() : scalings[row].diameter));
    columns.push_back(std::move(si));
    if (column.name == "d_mob") columns.push_back(aerodynamic_column(column, scalings));
  }
  table.columns = std::move(columns);
}

}  // namespace aerobreak
