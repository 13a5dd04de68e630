// Table (a) of docs/EXPORT.md: one row per grid point, from the grid-point statistics of the store.
#include <algorithm>
#include <cmath>
#include <functional>

#include "engine/core/units.hpp"
#include "orchestrator/export/equivalent_diameters.hpp"
#include "orchestrator/export/lookup_tables.hpp"

namespace aerobreak {
namespace {

struct GridRow {
  const GridRowInputs& inputs;
  const GridPointStatistics* statistics;     // nullptr: no result
  const GridPointFragmentMasses* fragments;  // nullptr: no determined result
};

struct ColumnSpec {
  const char* name;
  const char* unit;
  const char* description;
  ColumnRole role;
  std::function<double(const GridRow&)> value;
};

std::size_t results(const GridRow& row) { return row.statistics ? row.statistics->outcomes.finished() : 0; }

std::function<double(const GridRow&)> probability(const std::string& outcome, int bound) {
  return [outcome, bound](const GridRow& row) {
    if (!row.statistics) return kMissing;
    const GridPointOutcomes& counts = row.statistics->outcomes;
    const auto estimate = wilson_interval(counts.outcomes.at(outcome), counts.trials_for(outcome));
    if (!estimate) return kMissing;
    return bound < 0 ? estimate->lower : bound > 0 ? estimate->upper : estimate->probability;
  };
}

std::function<double(const GridRow&)> moment_mean(Moments GridPointStatistics::*member, bool standard_deviation) {
  return [member, standard_deviation](const GridRow& row) {
    if (!row.statistics) return kMissing;
    const auto estimate = mean_estimate(row.statistics->*member);
    if (!estimate) return kMissing;
    if (!standard_deviation) return estimate->mean;
    return estimate->standard_deviation.value_or(kMissing);
  };
}

// The k-th moment of the sizes (primaries) of the re-entrained fragments, per determined result.
std::function<double(const GridRow&)> reentrained_moment(int k) {
  return [k](const GridRow& row) {
    if (!row.fragments || row.fragments->results == 0) return kMissing;
    double sum = 0.0;
    for (const auto& fragment_class : row.fragments->classes)
      if (!fragment_class.on_wall)
        sum +=
            static_cast<double>(fragment_class.fragments) * std::pow(static_cast<double>(fragment_class.primaries), k);
    return sum / static_cast<double>(row.fragments->results);
  };
}

double monomer_mass_fraction(const GridRow& row) {
  if (!row.fragments) return kMissing;
  double monomers = 0.0, total = 0.0;
  for (const auto& fragment_class : row.fragments->classes) {
    total += fragment_class.mass;
    if (!fragment_class.on_wall && fragment_class.primaries == 1) monomers += fragment_class.mass;
  }
  return total > 0.0 ? monomers / total : kMissing;
}

double share_of_results(const GridRow& row, std::size_t GridPointOutcomes::*count) {
  const std::size_t n = results(row);
  return n ? static_cast<double>(row.statistics->outcomes.*count) / static_cast<double>(n) : kMissing;
}

double lambda(const GridRow& row) {
  return adhesion_energy_ratio(reduced_material(row.inputs.gamma_over_kn, row.inputs.poisson_ratio), 1.0,
                               row.inputs.speed);
}

std::vector<ColumnSpec> input_columns() {
  return {
      {"impact_speed", "d/tau", "normal impact speed v0", ColumnRole::speed,
       [](const GridRow& r) { return r.inputs.speed; }},
      {"primaries", "1", "primaries N in the cluster", ColumnRole::input,
       [](const GridRow& r) { return r.inputs.primaries; }},
      {"d_ve", "d", "volume-equivalent diameter d N^(1/3)", ColumnRole::derived,
       [](const GridRow& r) { return volume_equivalent_diameter(r.inputs.primaries); }},
      {"d_mob", "d", "mobility-equivalent diameter, free-molecular regime, d N^(1/(2*1.08)) (docs/EXPORT.md)",
       ColumnRole::derived, [](const GridRow& r) { return mobility_equivalent_diameter(r.inputs.primaries); }},
      {"gamma_over_kn", "1", "adhesion-to-stiffness ratio gamma/k_n", ColumnRole::input,
       [](const GridRow& r) { return r.inputs.gamma_over_kn; }},
      {"impact_angle", "deg", "impact angle from head-on", ColumnRole::input,
       [](const GridRow& r) { return r.inputs.angle; }},
      {"fractal_dimension", "1", "the generator's target fractal dimension Df (missing: not set, e.g. ballistic)",
       ColumnRole::input, [](const GridRow& r) { return r.inputs.fractal_dimension; }},
      {"lambda", "1", "adhesion over kinetic energy of one primary, report eq 19", ColumnRole::derived, lambda},
  };
}

std::vector<ColumnSpec> output_columns() {
  return {
      {"energy_per_contact", "1", "mean E_kin/(N_c E_break) of the results", ColumnRole::output,
       moment_mean(&GridPointStatistics::energy_per_contact, false)},
      {"results", "1", "results n (cases finished with a result)", ColumnRole::output,
       [](const GridRow& r) { return static_cast<double>(results(r)); }},
      {"p_stick", "1", "P(stick) = k/n_d, of the determined results", ColumnRole::output, probability("stick", 0)},
      {"p_stick_lo", "1", "P(stick), Wilson 95 % lower bound", ColumnRole::output, probability("stick", -1)},
      {"p_stick_hi", "1", "P(stick), Wilson 95 % upper bound", ColumnRole::output, probability("stick", 1)},
      {"p_bounce", "1", "P(bounce)", ColumnRole::output, probability("bounce", 0)},
      {"p_bounce_lo", "1", "P(bounce), Wilson 95 % lower bound", ColumnRole::output, probability("bounce", -1)},
      {"p_bounce_hi", "1", "P(bounce), Wilson 95 % upper bound", ColumnRole::output, probability("bounce", 1)},
      {"p_break_up", "1", "P(break-up)", ColumnRole::output, probability("break-up", 0)},
      {"p_break_up_lo", "1", "P(break-up), Wilson 95 % lower bound", ColumnRole::output, probability("break-up", -1)},
      {"p_break_up_hi", "1", "P(break-up), Wilson 95 % upper bound", ColumnRole::output, probability("break-up", 1)},
      {"p_undetermined", "1", "share of results that reached the time limit unsettled", ColumnRole::output,
       probability("undetermined", 0)},
      {"retained_mass_fraction", "1", "mean mass fraction retained on the wall", ColumnRole::output,
       moment_mean(&GridPointStatistics::retained_mass_fraction, false)},
      {"retained_mass_fraction_sd", "1", "its standard deviation over the results", ColumnRole::output,
       moment_mean(&GridPointStatistics::retained_mass_fraction, true)},
      {"restitution", "1", "mean normal restitution e_n of the bounces (missing where none bounced)",
       ColumnRole::output, moment_mean(&GridPointStatistics::restitution, false)},
      {"restitution_sd", "1", "its standard deviation over the bounces", ColumnRole::output,
       moment_mean(&GridPointStatistics::restitution, true)},
      {"restitution_bounces", "1", "bounces the restitution is averaged over", ColumnRole::output,
       [](const GridRow& r) { return r.statistics ? static_cast<double>(r.statistics->restitution.count) : kMissing; }},
      {"damage_ratio", "1", "mean damage ratio (initial contacts broken / initial contacts)", ColumnRole::output,
       moment_mean(&GridPointStatistics::damage_ratio, false)},
      {"largest_fragment_share", "1", "mean share of the primaries in the largest fragment", ColumnRole::output,
       moment_mean(&GridPointStatistics::largest_fragment_share, false)},
      {"reentrained_m0", "1", "re-entrained fragments per impact, sum of N_f^0 (determined results)",
       ColumnRole::output, reentrained_moment(0)},
      {"reentrained_m1", "1", "re-entrained primaries per impact, sum of N_f", ColumnRole::output,
       reentrained_moment(1)},
      {"reentrained_m2", "1", "sum of N_f^2 over the re-entrained fragments, per impact", ColumnRole::output,
       reentrained_moment(2)},
      {"reentrained_m3", "1", "sum of N_f^3 over the re-entrained fragments, per impact", ColumnRole::output,
       reentrained_moment(3)},
      {"monomer_mass_fraction", "1", "mass fraction re-entrained as single primaries", ColumnRole::output,
       monomer_mass_fraction},
      {"fractured_on_wall", "1", "share of results whose deposit is in pieces", ColumnRole::output,
       [](const GridRow& r) { return share_of_results(r, &GridPointOutcomes::fractured_on_wall); }},
      {"small_strain_exceeded", "1", "share of results flagged outside the contact laws' small-strain range",
       ColumnRole::output,
       [](const GridRow& r) { return share_of_results(r, &GridPointOutcomes::small_strain_exceeded); }},
  };
}

void add_extra_axes(LookupTable& table, const StudyExportData& data) {
  for (const auto& axis : data.extra_axes) {
    auto& column = table.add(axis.name, axis.unit(), axis.description(), ColumnRole::input);
    for (const auto& inputs : data.inputs) column.values.push_back(axis.value(inputs.grid_point));
  }
  add_axis_labels(table.metadata, data.extra_axes);
}

// A grid table of an adaptive search (docs/ADAPTIVE.md) says what its rows are and which table to
// read instead (docs/EXPORT.md, "An adaptive search's tables"): the header of every format shows it.
void add_search_note(LookupTable& table, const nlohmann::ordered_json& study) {
  if (!study.is_object() || !study.contains("search")) return;
  const auto& search = study.at("search");
  table.metadata["search"] = {
      {"axis", search.is_object() ? search.value("axis", std::string("impact_speed")) : std::string("impact_speed")},
      {"note", kSearchedGridNote}};
}

template <typename Map>
const typename Map::mapped_type* find_in(const Map& map, const std::string& key) {
  const auto found = map.find(key);
  return found == map.end() ? nullptr : &found->second;
}

}  // namespace

LookupTable grid_table(const StudyExportData& data) {
  LookupTable table;
  table.kind = "grid";
  auto specs = input_columns();
  const std::size_t input_count = specs.size();
  for (auto& spec : output_columns()) specs.push_back(std::move(spec));
  for (std::size_t c = 0; c < specs.size(); ++c) {
    if (c == input_count) add_extra_axes(table, data);
    auto& column = table.add(specs[c].name, specs[c].unit, specs[c].description, specs[c].role);
    for (const auto& inputs : data.inputs) {
      const GridRow row{inputs, find_in(data.statistics, inputs.grid_key), find_in(data.fragments, inputs.grid_key)};
      column.values.push_back(specs[c].value(row));
    }
  }
  add_search_note(table, data.study.document);
  // An input that no grid point has (e.g. the target fractal dimension of a ballistic generator)
  // does not apply: no column.
  std::erase_if(table.columns, [](const TableColumn& column) {
    return column.role == ColumnRole::input &&
           std::all_of(column.values.begin(), column.values.end(), [](double v) { return std::isnan(v); });
  });
  return table;
}

}  // namespace aerobreak
