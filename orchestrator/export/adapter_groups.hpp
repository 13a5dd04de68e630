#pragma once
#include <string>
#include <vector>

#include "orchestrator/export/lookup_table.hpp"

namespace aerobreak {

// The rows of a table split into impact conditions for the system-code adapters (MELCOR,
// OpenFOAM): rows that share every input but the speed, each condition's rows ascending in speed,
// rows where `quantity` is missing left out.
struct ConditionRows {
  std::vector<std::pair<std::string, double>> key;  // the condition's inputs (name, value)
  std::vector<std::size_t> rows;                    // ascending speed
};

// The speed column the adapters read: impact_speed_m_s when the table has SI, else impact_speed.
const TableColumn& adapter_speed(const LookupTable& table);
// The size column: d_ve_m, d_ve, source_d_ve_lower_m or source_d_ve_lower, the first present.
const TableColumn* adapter_size(const LookupTable& table);

// Conditions keyed on every input column except `left_out` (and the speed).
std::vector<ConditionRows> condition_rows(const LookupTable& table, const TableColumn& quantity,
                                          const std::vector<std::string>& left_out = {});

}  // namespace aerobreak
