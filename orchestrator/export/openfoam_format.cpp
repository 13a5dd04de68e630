// OpenFOAM tables (docs/EXPORT.md, "OpenFOAM"): interpolation2DTable, a list of
// (x ((y value) ...)) ascending in x and in y (OpenFOAM src/OpenFOAM/interpolations/
// interpolation2DTable/interpolation2DTable.H), and the data and entries of a Function1 csvFile
// (src/OpenFOAM/primitives/functions/Function1/CSV/CSV.H: nHeaderLine, refColumn,
// componentColumns, separator, mergeSeparators, file, outOfBounds, interpolationScheme).
#include <algorithm>
#include <map>
#include <set>

#include "orchestrator/export/adapter_groups.hpp"
#include "orchestrator/export/export_request.hpp"
#include "orchestrator/export/table_formats.hpp"

namespace aerobreak {
namespace {

// Inputs that vary with the size, not keys of an impact condition (a fit table's `model` changes
// with N where a size the study did not run comes from the fit pooled over the sizes).
const char* kSizeInputs[] = {"primaries", "source_section", "model"};

constexpr const char* kOutOfBounds =
    "outside its speeds and sizes this table has no value: read it with outOfBounds error (a clamp would return the "
    "value at the edge as if it held beyond)";

const TableColumn& quantity_column(const LookupTable& table, const std::string& quantity) {
  const std::string name = quantity == "retained_mass_fraction" && !table.find(quantity) ? "to_wall" : quantity;
  if (const auto* column = table.find(name)) return *column;
  throw ExportError(422, "quantity", "this table (kind " + table.kind + ") has no column '" + quantity + "'");
}

// The inputs whose values differ between the conditions (e.g. wall_adhesive, gamma_over_kn).
std::vector<std::string> differing_inputs(const std::vector<ConditionRows>& conditions) {
  std::vector<std::string> names;
  for (const auto& [name, value] : conditions.front().key)
    for (const auto& condition : conditions) {
      const auto same = std::find_if(condition.key.begin(), condition.key.end(),
                                     [&](const auto& entry) { return entry.first == name; });
      if (same == condition.key.end() || same->second != value) {
        names.push_back(name);
        break;
      }
    }
  return names;
}

// 422 naming the inputs that tell the conditions apart and what selects one of them.
[[noreturn]] void refuse_several_conditions(const std::vector<ConditionRows>& conditions) {
  std::string differing, example;
  for (const auto& name : differing_inputs(conditions)) differing += (differing.empty() ? "" : ", ") + name;
  for (const auto& [name, value] : conditions[1].key) example += " " + name + "=" + number_text(value);
  throw ExportError(422, "format",
                    "an OpenFOAM table holds one impact condition besides speed and size, and this table has " +
                        std::to_string(conditions.size()) + " conditions differing in " + differing + " (e.g." +
                        example +
                        "): choose gamma/k_n with a material or gamma_over_kn, any other input with select=NAME:VALUE "
                        "(e.g. select=wall_adhesive:1), or use format=melcor (one tabular function per condition)");
}

// value[speed][size] of the table's one impact condition (besides speed and size).
std::map<double, std::map<double, double>> speed_size_values(const LookupTable& table, const TableColumn& quantity) {
  const auto conditions = condition_rows(table, quantity, {std::begin(kSizeInputs), std::end(kSizeInputs)});
  if (conditions.size() > 1) refuse_several_conditions(conditions);
  const auto& speed = adapter_speed(table);
  const auto* size = adapter_size(table);
  if (!size) throw ExportError(422, "format", "this table has no size column");
  std::map<double, std::map<double, double>> values;
  if (!conditions.empty())
    for (const std::size_t row : conditions.front().rows)
      values[speed.values[row]][size->values[row]] = quantity.values[row];
  return values;
}

// The header's last line says what happens outside the table, as the entries and docs/EXPORT.md
// ask OpenFOAM to do it: stop, neither extrapolate nor clamp silently.
std::string header(const LookupTable& table, const std::string& what) {
  std::string text = "// aerobreak lookup table: " + what + " (docs/EXPORT.md)\n";
  for (const auto& [key, value] : metadata_lines(table.metadata)) text += "// " + key + ": " + value + "\n";
  return text + "// " + kOutOfBounds + "\n";
}

// The sizes every speed has: the columns of the csvFile data.
std::vector<double> common_sizes(const std::map<double, std::map<double, double>>& values) {
  std::set<double> sizes;
  for (const auto& [speed, by_size] : values)
    for (const auto& [size, value] : by_size) sizes.insert(size);
  std::vector<double> common;
  for (const double size : sizes)
    if (std::all_of(values.begin(), values.end(), [size](const auto& entry) { return entry.second.count(size) > 0; }))
      common.push_back(size);
  return common;
}

}  // namespace

std::string openfoam_table2d(const LookupTable& table, const std::string& quantity) {
  const auto& column = quantity_column(table, quantity);
  const auto values = speed_size_values(table, column);
  std::string text = header(table, column.name + " [" + column.unit + "] over (x = impact speed [" +
                                       adapter_speed(table).unit + "], y = " + adapter_size(table)->name + " [" +
                                       adapter_size(table)->unit + "]) as an OpenFOAM interpolation2DTable");
  text += "(\n";
  for (const auto& [speed, by_size] : values) {
    text += "    (" + number_text(speed) + " (";
    for (const auto& [size, value] : by_size) text += " (" + number_text(size) + " " + number_text(value) + ")";
    text += " ))\n";
  }
  return text + ")\n";
}

std::string openfoam_csv(const LookupTable& table, const std::string& quantity) {
  const auto& column = quantity_column(table, quantity);
  const auto values = speed_size_values(table, column);
  const auto sizes = common_sizes(values);
  std::string text = adapter_speed(table).name;
  for (const double size : sizes) {
    text += ',';
    text += column.name + "_at_" + adapter_size(table)->name + "_" + number_text(size);
  }
  text += "\n";
  for (const auto& [speed, by_size] : values) {
    text += number_text(speed);
    for (const double size : sizes) {
      text += ',';
      text += number_text(by_size.at(size));
    }
    text += "\n";
  }
  return text;
}

std::string openfoam_dictionary(const LookupTable& table, const std::string& quantity, const std::string& csv_file) {
  const auto& column = quantity_column(table, quantity);
  const auto sizes = common_sizes(speed_size_values(table, column));
  std::string text = header(table, "Function1 csvFile entries of " + column.name + " against impact speed [" +
                                       adapter_speed(table).unit + "], one per size");
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    const std::string entry = column.name + "_" + std::to_string(i + 1);
    text += "\n// " + adapter_size(table)->name + " = " + number_text(sizes[i]) + " " + adapter_size(table)->unit +
            "\n" + entry + " csvFile;\n" + entry +
            "Coeffs\n{\n    nHeaderLine         1;\n    refColumn           0;\n" + "    componentColumns    (" +
            std::to_string(i + 1) + ");\n    separator           \",\";\n" +
            "    mergeSeparators     no;\n    file                \"" + csv_file + "\";\n" +
            "    outOfBounds         error;\n    interpolationScheme linear;\n}\n";
  }
  return text;
}

}  // namespace aerobreak
