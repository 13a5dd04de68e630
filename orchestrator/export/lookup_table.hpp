#pragma once
#include <cstddef>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace aerobreak {

// The lookup tables for system codes (docs/EXPORT.md): one table model, built from a study's
// stored results (kind grid or sections) or fits (kind fit), rendered to each format by
// table_formats.hpp. A table is a list of numeric columns of equal length; a missing value is NaN
// (empty in CSV, null in JSON, NaN in .dat and HDF5, left out of MELCOR and OpenFOAM tables).

inline constexpr double kMissing = std::numeric_limits<double>::quiet_NaN();

// What a column stands for in the adapters: the impact speed (their x), another input that sets
// the impact condition (a table's group key), an input derived from those (equivalent diameters,
// lambda, SI copies: shown, never a key) or an output.
enum class ColumnRole { speed, input, derived, output };

struct TableColumn {
  std::string name;  // [a-z0-9_], the same in every format
  std::string unit;  // "1" for a dimensionless number, "d/tau", "d", "m/s", "m", ...
  std::string description;
  ColumnRole role = ColumnRole::output;
  std::vector<double> values;
};

struct LookupTable {
  std::string kind;                 // grid | sections | fit
  nlohmann::ordered_json metadata;  // provenance, units, validity, ... (header block, attributes)
  std::vector<TableColumn> columns;

  std::size_t rows() const { return columns.empty() ? 0 : columns.front().values.size(); }
  // The column of that name; nullptr when there is none.
  const TableColumn* find(std::string_view name) const;
  TableColumn* find(std::string_view name);
  TableColumn& add(std::string name, std::string unit, std::string description, ColumnRole role = ColumnRole::output);
};

// The metadata as "key: value" lines (nested objects as dotted keys, arrays as JSON), in order:
// the header block of the text formats.
std::vector<std::pair<std::string, std::string>> metadata_lines(const nlohmann::ordered_json& metadata);

// A value as a key of an ordered map: NaN (which compares false with everything) as -infinity.
double key_value(double value);

// A value as text with 10 significant digits (%.9e), "NaN" when missing: the precision of every
// text format.
std::string number_text(double value);

}  // namespace aerobreak
