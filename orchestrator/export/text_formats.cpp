// The neutral text formats of docs/EXPORT.md: RFC 4180 CSV, whitespace .dat for Fortran, JSON.
#include <cmath>

#include "orchestrator/export/table_formats.hpp"

namespace aerobreak {
namespace {

// RFC 4180 section 2, rules 5-7: a field with a comma, quote, CR or LF is quoted, quotes doubled.
std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string csv_record(const std::vector<std::string>& fields, std::size_t width) {
  std::string record;
  for (std::size_t i = 0; i < std::max(width, fields.size()); ++i) {
    if (i > 0) record += ',';
    if (i < fields.size()) record += csv_field(fields[i]);
  }
  return record + "\r\n";
}

std::string role_name(ColumnRole role) {
  switch (role) {
    case ColumnRole::speed: return "speed";
    case ColumnRole::input: return "input";
    case ColumnRole::derived: return "derived";
    case ColumnRole::output: return "output";
  }
  return "output";
}

}  // namespace

std::string csv_text(const LookupTable& table) {
  const std::size_t width = std::max<std::size_t>(table.columns.size(), 2);
  const auto lines = metadata_lines(table.metadata);
  std::string text = csv_record({"#header_lines", std::to_string(lines.size() + 1)}, width);
  for (const auto& [key, value] : lines) text += csv_record({"#" + key, value}, width);
  std::vector<std::string> names, units;
  for (const auto& column : table.columns) names.push_back(column.name), units.push_back(column.unit);
  text += csv_record(names, width) + csv_record(units, width);
  for (std::size_t row = 0; row < table.rows(); ++row) {
    std::vector<std::string> fields;
    for (const auto& column : table.columns)
      fields.push_back(std::isnan(column.values[row]) ? std::string() : number_text(column.values[row]));
    text += csv_record(fields, width);
  }
  return text;
}

std::string dat_text(const LookupTable& table) {
  std::string text = "# aerobreak lookup table, whitespace-separated for Fortran list-directed input (docs/EXPORT.md)\n";
  for (const auto& [key, value] : metadata_lines(table.metadata)) text += "# " + key + ": " + value + "\n";
  text += "# columns: " + std::to_string(table.columns.size()) + "\n# rows: " + std::to_string(table.rows()) + "\n";
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    const auto& column = table.columns[c];
    text += "# column " + std::to_string(c + 1) + ": " + column.name + " [" + column.unit + "] " + column.description + "\n";
  }
  for (std::size_t row = 0; row < table.rows(); ++row) {
    for (std::size_t c = 0; c < table.columns.size(); ++c)
      text += (c == 0 ? " " : "  ") + number_text(table.columns[c].values[row]);
    text += "\n";
  }
  return text;
}

nlohmann::ordered_json table_json(const LookupTable& table) {
  nlohmann::ordered_json columns = nlohmann::ordered_json::array();
  for (const auto& column : table.columns) {
    nlohmann::ordered_json values = nlohmann::ordered_json::array();
    for (const double value : column.values) values.push_back(std::isnan(value) ? nlohmann::ordered_json() : nlohmann::ordered_json(value));
    columns.push_back({{"name", column.name}, {"unit", column.unit}, {"description", column.description},
                       {"role", role_name(column.role)}, {"values", values}});
  }
  return {{"format", "aerobreak-lookup-table"}, {"format_version", 1},       {"kind", table.kind},
          {"metadata", table.metadata},          {"rows", table.rows()},      {"columns", columns}};
}

}  // namespace aerobreak
