#pragma once
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "engine/impact/json_schema.hpp"

namespace aerobreak {

// What a case that fails its schema most likely meant, so that its errors say how to mend it.

// A material given in the other unit system than "units" says (SI fields without "units":
// "physical", or gamma_over_kn with it): the "units" the case meant and why, as a violation at
// /units; nullopt when the material fits its units or is neither.
struct UnitsHint {
  std::string meant_units;
  SchemaViolation violation;
};
std::optional<UnitsHint> units_hint(const nlohmann::ordered_json& document);

// Appends to each range violation of an SI material field (e.g. "/material/diameter: must be <=
// 0.001 (got 20)") the unit it is read in, with an example of the usual slip: "in m: 20 nm is 2e-08".
void add_unit_hints(std::vector<SchemaViolation>& violations);

}  // namespace aerobreak
