// MELCOR 2 tabular functions (docs/EXPORT.md, "MELCOR"). Input syntax after the MELCOR Computer
// Code Manuals, Vol. 1: Primer and Users' Guide (SAND2017-0455 O), TF package: a TF_INPUT block,
// per function TF_ID 'name' scale and TF_TAB n followed by n records "i x y"; '!' starts a comment.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "orchestrator/export/adapter_groups.hpp"
#include "orchestrator/export/export_request.hpp"
#include "orchestrator/export/table_formats.hpp"

namespace aerobreak {
namespace {

// A tabulated column and its tag in the function's name (four characters).
struct TabulatedQuantity {
  std::string column;
  std::string tag;
};

// Every outcome's probability with its 95 % interval, the share of undetermined results (of the grid
// table: the probabilities are of the determined ones), the restitution, the retained mass, and for
// the sectional matrix the wall's share and each section's.
std::vector<TabulatedQuantity> tabulated(const LookupTable& table) {
  std::vector<TabulatedQuantity> quantities;
  for (const auto& [column, tag] : {std::pair{"p_stick", "PSTK"}, {"p_bounce", "PBNC"}, {"p_break_up", "PBRK"}})
    for (const auto& [suffix, bound] : {std::pair{"", "_"}, {"_lo", "L"}, {"_hi", "U"}})
      quantities.push_back({std::string(column) + suffix, std::string(tag) + bound});
  quantities.push_back({"p_undetermined", "PUND_"});
  quantities.push_back({"restitution", "REST_"});
  quantities.push_back({"retained_mass_fraction", "RETN_"});
  quantities.push_back({"to_wall", "WALL_"});
  for (int k = 1; k < 100; ++k) {
    char column[32], tag[8];
    std::snprintf(column, sizeof column, "to_section_%02d", k);
    std::snprintf(tag, sizeof tag, "TS%02d_", k);
    if (table.find(column)) quantities.push_back({column, tag});
  }
  return quantities;
}

// G grid, S sections, F a fit table at sizes; M, V, A a fit table at mobility, volume-equivalent or
// aerodynamic diameters (metadata sizes_from), so that the default files' names never collide.
char kind_letter(const LookupTable& table) {
  if (table.kind == "sections") return 'S';
  if (table.kind != "fit") return 'G';
  const std::string from = table.metadata.value("sizes_from", std::string());
  return from.starts_with("mobility")      ? 'M'
         : from.starts_with("volume")      ? 'V'
         : from.starts_with("aerodynamic") ? 'A'
                                           : 'F';
}

// S<study><kind><tag><bound><condition>: unique across studies, table kinds, quantities, interval
// ends and conditions (docs/EXPORT.md, "MELCOR").
std::string function_name(const LookupTable& table, const std::string& tag, std::size_t condition) {
  const auto study = table.metadata.at("provenance").at("study_id").get<std::int64_t>();
  char name[48];
  std::snprintf(name, sizeof name, "S%lld%c%s%03zu", static_cast<long long>(study), kind_letter(table), tag.c_str(),
                condition);
  if (std::string(name).size() > kMelcorNameLength)
    throw ExportError(422, "format",
                      std::string("MELCOR function name ") + name + " is longer than " +
                          std::to_string(kMelcorNameLength) + " characters (study id or conditions too many)");
  return name;
}

// The condition's inputs, and the derived columns that are the same on all its rows (a size's
// diameters; not lambda, which changes with the speed).
std::string condition_text(const LookupTable& table, const ConditionRows& condition) {
  std::string text;
  for (const auto& [name, value] : condition.key)
    text += (text.empty() ? "" : ", ") + name + " = " + number_text(value);
  for (const auto& column : table.columns) {
    if (column.role != ColumnRole::derived) continue;
    const double first = column.values[condition.rows.front()];
    const bool constant = std::all_of(condition.rows.begin(), condition.rows.end(),
                                      [&](std::size_t row) { return column.values[row] == first; });
    if (constant && !std::isnan(first)) text += (text.empty() ? "" : ", ") + column.name + " = " + number_text(first);
  }
  return text.empty() ? "(the table's one condition)" : text;
}

std::string tabular_function(const LookupTable& table, const TableColumn& quantity, const std::string& name,
                             const ConditionRows& condition, const std::vector<std::size_t>& rows) {
  const auto& speed = adapter_speed(table);
  std::string text = "!\n! " + name + ": " + quantity.name + " [" + quantity.unit + "] (" + quantity.description +
                     ") against impact speed [" + speed.unit + "] from " + number_text(speed.values[rows.front()]) +
                     " to " + number_text(speed.values[rows.back()]) + "\n! at " + condition_text(table, condition) +
                     "\nTF_ID '" + name + "' 1.0\nTF_TAB " + std::to_string(rows.size()) + " ! n x y\n";
  std::size_t i = 0;
  for (const std::size_t row : rows)
    text += "  " + std::to_string(++i) + "  " + number_text(speed.values[row]) + "  " +
            number_text(quantity.values[row]) + "\n";
  return text;
}

std::string legend(const LookupTable& table, const std::vector<ConditionRows>& conditions) {
  std::string text =
      "! names S<study id><table: G grid, F fit at sizes, M/V/A fit at mobility/volume/aerodynamic diameters, "
      "S sections>\n!   <quantity: PSTK P(stick), PBNC P(bounce), PBRK P(break-up) (of the determined results),\n"
      "!   PUND share of results undetermined, REST restitution of the "
      "bounces, RETN retained mass fraction, WALL mass to the wall, TSkk "
      "mass to section kk>\n!   <_ value, L 95 % lower end, U 95 % upper end><condition number, below>\n";
  text +=
      "! x: impact speed [" + adapter_speed(table).unit + "]; a function is left out where its quantity has no value\n";
  for (std::size_t c = 0; c < conditions.size(); ++c) {
    char number[24];
    std::snprintf(number, sizeof number, "%03zu", c + 1);
    text += "! condition " + std::string(number) + ": " + condition_text(table, conditions[c]) + "\n";
  }
  return text;
}

}  // namespace

std::string melcor_text(const LookupTable& table) {
  std::string text = "! aerobreak lookup table as MELCOR 2 tabular functions (docs/EXPORT.md)\n";
  for (const auto& [key, value] : metadata_lines(table.metadata)) text += "! " + key + ": " + value + "\n";
  const auto conditions = condition_rows(table, adapter_speed(table));
  text += legend(table, conditions) + "TF_INPUT\n";
  for (const auto& quantity : tabulated(table)) {
    const auto* column = table.find(quantity.column);
    if (!column) continue;
    for (std::size_t c = 0; c < conditions.size(); ++c) {
      std::vector<std::size_t> rows;
      for (const std::size_t row : conditions[c].rows)
        if (!std::isnan(column->values[row])) rows.push_back(row);
      if (!rows.empty())
        text += tabular_function(table, *column, function_name(table, quantity.tag, c + 1), conditions[c], rows);
    }
  }
  return text;
}

}  // namespace aerobreak
