#pragma once
#include <nlohmann/json.hpp>
#include <string>

namespace aerobreak {

// The units of a study's or a case's numbers (schemas/openapi.json, Units): SI for a physical
// study (its material and impact speeds are given in SI; results are reported in SI beside the
// reduced values), the report's reduced units otherwise (section 3.1: length d, mass m, time
// tau = sqrt(m/k_n), energy k_n d^2). Each entry names the unit of one kind of quantity.
// `system` is "physical", "reduced" or "mixed" (an axis sets /units: no one unit holds).
nlohmann::ordered_json units_json(const std::string& system);

// A case document's unit system: its "units" ("reduced" when absent).
std::string case_unit_system(const nlohmann::ordered_json& case_document);

// A study document's unit system: its base's "units" ("reduced" when absent), or "mixed" when an
// axis sets /units.
std::string study_unit_system(const nlohmann::ordered_json& study_document);

}  // namespace aerobreak
