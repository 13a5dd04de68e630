#include "orchestrator/export/lookup_table.hpp"

#include <cmath>
#include <cstdio>

namespace aerobreak {
namespace {

void flatten(const std::string& prefix, const nlohmann::ordered_json& value,
             std::vector<std::pair<std::string, std::string>>& lines) {
  if (value.is_object()) {
    for (const auto& [key, member] : value.items()) flatten(prefix.empty() ? key : prefix + "." + key, member, lines);
    return;
  }
  lines.emplace_back(prefix, value.is_string() ? value.get<std::string>() : value.dump());
}

}  // namespace

const TableColumn* LookupTable::find(std::string_view name) const {
  for (const auto& column : columns)
    if (column.name == name) return &column;
  return nullptr;
}

TableColumn* LookupTable::find(std::string_view name) {
  for (auto& column : columns)
    if (column.name == name) return &column;
  return nullptr;
}

TableColumn& LookupTable::add(std::string name, std::string unit, std::string description, ColumnRole role) {
  columns.push_back({std::move(name), std::move(unit), std::move(description), role, {}});
  return columns.back();
}

std::vector<std::pair<std::string, std::string>> metadata_lines(const nlohmann::ordered_json& metadata) {
  std::vector<std::pair<std::string, std::string>> lines;
  flatten("", metadata, lines);
  return lines;
}

double key_value(double value) { return std::isnan(value) ? -std::numeric_limits<double>::infinity() : value; }

std::string number_text(double value) {
  if (std::isnan(value)) return "NaN";
  char text[32];
  std::snprintf(text, sizeof text, "%.9e", value);
  return text;
}

}  // namespace aerobreak
