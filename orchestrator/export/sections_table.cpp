// Table (c) of docs/EXPORT.md: the sectional fragment matrix. Sections are geometric in mass (in
// primaries): section k = 1..K holds the fragments of r^(k-1) <= N < r^k primaries, r the section
// ratio (MAEROS's sections are geometric in particle mass with a ratio of at least 2: Gelbard &
// Seinfeld, J. Colloid Interface Sci. 78 (1980) 485). For each impact condition (every study axis
// but the size, boolean and text ones too) and source section j, column j of the matrix: B[k][j],
// the mass fraction of the clusters of section j that leaves the wall in fragments of section k,
// and the fraction retained on the wall; they sum to 1.
#include <cmath>
#include <map>
#include <tuple>

#include "orchestrator/export/equivalent_diameters.hpp"
#include "orchestrator/export/lookup_tables.hpp"
#include "orchestrator/fitting/proportion.hpp"

namespace aerobreak {
namespace {

int section_of(double primaries, double ratio) {
  return 1 + static_cast<int>(std::floor(std::log(primaries) / std::log(ratio) + 1e-12));
}

// The pooled fragments of the grid points that share an impact condition and a source section.
struct SourceCell {
  const GridRowInputs* inputs = nullptr;  // the first grid point of the cell
  int section = 0;
  double source_mass = 0.0;  // mass-weighted mean source size: sum N M / sum M
  double source_primaries_mass = 0.0;
  std::size_t results = 0;
  std::size_t break_ups = 0;
  double total_mass = 0.0;
  double wall_mass = 0.0;
  std::map<int, double> section_mass;  // re-entrained mass by section
};

// The full impact condition of a grid point: every axis but the source size (boolean and label
// axes too: the adhesive and the non-adhesive wall never share a matrix).
std::vector<double> condition_key(const GridRowInputs& inputs, const std::vector<AxisColumn>& extra_axes, int section) {
  std::vector<double> key{inputs.speed, inputs.gamma_over_kn, inputs.angle, static_cast<double>(section)};
  for (const auto& axis : extra_axes) key.push_back(key_value(axis.value(inputs.grid_point)));
  return key;
}

std::vector<SourceCell> pooled_cells(const StudyExportData& data, double ratio) {
  std::vector<SourceCell> cells;
  std::map<std::vector<double>, std::size_t> index;
  for (const auto& inputs : data.inputs) {
    const auto found = data.fragments.find(inputs.grid_key);
    if (found == data.fragments.end() || found->second.results == 0) continue;
    const int section = section_of(inputs.primaries, ratio);
    const auto [slot, inserted] = index.emplace(condition_key(inputs, data.extra_axes, section), cells.size());
    if (inserted) {
      cells.emplace_back();
      cells.back().inputs = &inputs;
      cells.back().section = section;
    }
    SourceCell& cell = cells[slot->second];
    cell.results += found->second.results;
    cell.break_ups += found->second.break_ups;
    for (const auto& fragment_class : found->second.classes) {
      cell.total_mass += fragment_class.mass;
      cell.source_primaries_mass += inputs.primaries * fragment_class.mass;
      if (fragment_class.on_wall)
        cell.wall_mass += fragment_class.mass;
      else
        cell.section_mass[section_of(static_cast<double>(fragment_class.primaries), ratio)] += fragment_class.mass;
    }
  }
  return cells;
}

int section_count(const StudyExportData& data, double ratio) {
  double largest = 1.0;
  for (const auto& inputs : data.inputs) largest = std::max(largest, inputs.primaries);
  return section_of(largest, ratio);
}

void add_condition_columns(LookupTable& table, const std::vector<SourceCell>& cells, const StudyExportData& data,
                           double ratio) {
  auto add = [&](const char* name, const char* unit, const char* description, ColumnRole role, auto value) {
    auto& column = table.add(name, unit, description, role);
    for (const auto& cell : cells) column.values.push_back(value(cell));
  };
  add("impact_speed", "d/tau", "normal impact speed v0", ColumnRole::speed,
      [](const SourceCell& c) { return c.inputs->speed; });
  add("gamma_over_kn", "1", "adhesion-to-stiffness ratio gamma/k_n", ColumnRole::input,
      [](const SourceCell& c) { return c.inputs->gamma_over_kn; });
  add("impact_angle", "deg", "impact angle from head-on", ColumnRole::input,
      [](const SourceCell& c) { return c.inputs->angle; });
  for (const auto& axis : data.extra_axes) {
    auto& column = table.add(axis.name, axis.unit(), axis.description(), ColumnRole::input);
    for (const auto& cell : cells) column.values.push_back(axis.value(cell.inputs->grid_point));
  }
  add_axis_labels(table.metadata, data.extra_axes);
  add("source_section", "1", "source section j of the impacting clusters", ColumnRole::input,
      [](const SourceCell& c) { return static_cast<double>(c.section); });
  add("source_d_ve_lower", "d", "lower volume-equivalent diameter of section j", ColumnRole::derived,
      [ratio](const SourceCell& c) { return volume_equivalent_diameter(std::pow(ratio, c.section - 1)); });
  add("source_d_ve_upper", "d", "upper volume-equivalent diameter of section j", ColumnRole::derived,
      [ratio](const SourceCell& c) { return volume_equivalent_diameter(std::pow(ratio, c.section)); });
  add("source_primaries", "1", "mass-weighted mean size of the impacting clusters of the row", ColumnRole::derived,
      [](const SourceCell& c) { return c.source_primaries_mass / c.total_mass; });
}

void add_matrix_columns(LookupTable& table, const std::vector<SourceCell>& cells, int sections) {
  auto add = [&](std::string name, std::string description, auto value) {
    auto& column = table.add(std::move(name), "1", std::move(description), ColumnRole::output);
    for (const auto& cell : cells) column.values.push_back(value(cell));
  };
  add("results", "determined results pooled in the row",
      [](const SourceCell& c) { return static_cast<double>(c.results); });
  for (const int bound : {0, -1, 1})
    add(bound == 0  ? "p_break_up"
        : bound < 0 ? "p_break_up_lo"
                    : "p_break_up_hi",
        bound == 0 ? "P(break-up) over the determined results" : "P(break-up), Wilson 95 % bound",
        [bound](const SourceCell& c) {
          const auto estimate = *wilson_interval(c.break_ups, c.results);
          return bound == 0 ? estimate.probability : bound < 0 ? estimate.lower : estimate.upper;
        });
  add("to_wall", "mass fraction retained on the wall", [](const SourceCell& c) { return c.wall_mass / c.total_mass; });
  for (int k = 1; k <= sections; ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "to_section_%02d", k);
    add(name, "mass fraction re-entrained in fragments of section " + std::to_string(k), [k](const SourceCell& c) {
      const auto found = c.section_mass.find(k);
      return found == c.section_mass.end() ? 0.0 : found->second / c.total_mass;
    });
  }
}

// Each section's bounds: [primaries from, below, d_ve from, below, d_mob from, below] (in d).
nlohmann::ordered_json section_bounds(int sections, double ratio) {
  nlohmann::ordered_json bounds{
      {"fields", "primaries_from primaries_below d_ve_from d_ve_below d_mob_from d_mob_below"}};
  for (int k = 1; k <= sections; ++k) {
    const double lower = std::pow(ratio, k - 1), upper = std::pow(ratio, k);
    char name[32];
    std::snprintf(name, sizeof name, "section_%02d", k);
    bounds[name] = {lower,
                    upper,
                    volume_equivalent_diameter(lower),
                    volume_equivalent_diameter(upper),
                    mobility_equivalent_diameter(lower),
                    mobility_equivalent_diameter(upper)};
  }
  return bounds;
}

}  // namespace

LookupTable sections_table(const StudyExportData& data, double section_ratio) {
  LookupTable table;
  table.kind = "sections";
  const auto cells = pooled_cells(data, section_ratio);
  const int sections = section_count(data, section_ratio);
  add_condition_columns(table, cells, data, section_ratio);
  add_matrix_columns(table, cells, sections);
  table.metadata["sections"] = {
      {"ratio", section_ratio}, {"count", sections}, {"bounds", section_bounds(sections, section_ratio)}};
  return table;
}

}  // namespace aerobreak
