// The neutral text formats of docs/EXPORT.md: RFC 4180 CSV, whitespace .dat for Fortran, JSON.
#include <algorithm>
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
    case ColumnRole::speed:
      return "speed";
    case ColumnRole::input:
      return "input";
    case ColumnRole::derived:
      return "derived";
    case ColumnRole::output:
      return "output";
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

namespace {

// `text` after `prefix` on comment lines of at most kDatLineWidth characters, continued on lines
// starting "#  "; a word longer than a line is cut.
std::string comment_lines(const std::string& prefix, const std::string& text) {
  const std::string continuation = "#  ";
  const std::size_t longest = kDatLineWidth - continuation.size() - 1;
  std::string out, line = prefix;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = std::min(text.find(' ', start), text.size());
    for (std::size_t piece = start; piece < end; piece += longest) {
      const std::string word = text.substr(piece, std::min(longest, end - piece));
      if (line.size() + 1 + word.size() > kDatLineWidth) out += line + "\n", line = continuation;
      line += " " + word;
    }
    start = end + 1;
  }
  return out + line + "\n";
}

// The value as .dat writes it: the missing-value sentinel where there is none (no NaN: a reader
// built to trap invalid operations must never meet one).
std::string dat_number(double value) { return number_text(std::isnan(value) ? kDatMissingValue : value); }

}  // namespace

std::string dat_text(const LookupTable& table) {
  std::string header =
      comment_lines("#",
                    "aerobreak lookup table for Fortran list-directed input (docs/EXPORT.md): lines of "
                    "at most 80 characters; a row is one list-directed READ of `columns` values over "
                    "its lines; a missing value is the sentinel missing_value");
  for (const auto& [key, value] : metadata_lines(table.metadata))
    if (key != "missing_value") header += comment_lines("# " + key + ":", value);
  header += "# missing_value: " + dat_number(kMissing) + "\n";
  header += "# columns: " + std::to_string(table.columns.size()) + "\n# rows: " + std::to_string(table.rows()) + "\n";
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    const auto& column = table.columns[c];
    header += "# column " + std::to_string(c + 1) + " " + column.name + " '" + column.unit + "'\n";
    header += comment_lines("#  ", column.description);
  }
  const auto lines = static_cast<std::size_t>(std::count(header.begin(), header.end(), '\n'));
  std::string text = "# aerobreak lookup table (.dat)\n# header_lines: " + std::to_string(lines + 2) + "\n" + header;
  for (std::size_t row = 0; row < table.rows(); ++row)
    for (std::size_t c = 0; c < table.columns.size(); ++c)
      text += (c % kDatValuesPerLine == 0 ? " " : "  ") + dat_number(table.columns[c].values[row]) +
              (c % kDatValuesPerLine == kDatValuesPerLine - 1 || c + 1 == table.columns.size() ? "\n" : "");
  return text;
}

nlohmann::ordered_json table_json(const LookupTable& table) {
  nlohmann::ordered_json columns = nlohmann::ordered_json::array();
  for (const auto& column : table.columns) {
    nlohmann::ordered_json values = nlohmann::ordered_json::array();
    for (const double value : column.values)
      values.push_back(std::isnan(value) ? nlohmann::ordered_json() : nlohmann::ordered_json(value));
    columns.push_back({{"name", column.name},
                       {"unit", column.unit},
                       {"description", column.description},
                       {"role", role_name(column.role)},
                       {"values", values}});
  }
  return {{"format", "aerobreak-lookup-table"}, {"format_version", 1},  {"kind", table.kind},
          {"metadata", table.metadata},         {"rows", table.rows()}, {"columns", columns}};
}

}  // namespace aerobreak
