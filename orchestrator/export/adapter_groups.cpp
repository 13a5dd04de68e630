#include "orchestrator/export/adapter_groups.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "orchestrator/export/export_request.hpp"

namespace aerobreak {

const TableColumn& adapter_speed(const LookupTable& table) {
  if (const auto* si = table.find("impact_speed_m_s")) return *si;
  if (const auto* reduced = table.find("impact_speed")) return *reduced;
  throw ExportError(422, "kind", "this table has no impact speed column");
}

const TableColumn* adapter_size(const LookupTable& table) {
  for (const char* name : {"d_ve_m", "d_ve", "source_d_ve_lower_m", "source_d_ve_lower"})
    if (const auto* column = table.find(name)) return column;
  return nullptr;
}

std::vector<ConditionRows> condition_rows(const LookupTable& table, const TableColumn& quantity,
                                          const std::vector<std::string>& left_out) {
  std::vector<const TableColumn*> keys;
  for (const auto& column : table.columns)
    if (column.role == ColumnRole::input && std::find(left_out.begin(), left_out.end(), column.name) == left_out.end())
      keys.push_back(&column);
  std::map<std::vector<double>, std::size_t> index;
  std::vector<ConditionRows> conditions;
  for (std::size_t row = 0; row < table.rows(); ++row) {
    if (std::isnan(quantity.values[row])) continue;
    std::vector<double> key;
    for (const auto* column : keys) key.push_back(key_value(column->values[row]));
    const auto [slot, inserted] = index.emplace(key, conditions.size());
    if (inserted) {
      ConditionRows condition;
      for (const auto* column : keys)
        if (!std::isnan(column->values[row])) condition.key.emplace_back(column->name, column->values[row]);
      conditions.push_back(std::move(condition));
    }
    conditions[slot->second].rows.push_back(row);
  }
  const auto& speed = adapter_speed(table);
  for (auto& condition : conditions)
    std::sort(condition.rows.begin(), condition.rows.end(),
              [&](std::size_t a, std::size_t b) { return speed.values[a] < speed.values[b]; });
  return conditions;
}

}  // namespace aerobreak
