#include "engine/impact/case_hints.hpp"

#include <algorithm>
#include <array>
#include <string_view>

namespace aerobreak {
namespace {

using Json = nlohmann::ordered_json;

constexpr std::array<std::string_view, 4> kSiMaterialFields{"youngs_modulus", "density", "surface_energy", "diameter"};

bool has_any_si_field(const Json& material) {
  return std::any_of(kSiMaterialFields.begin(), kSiMaterialFields.end(),
                     [&](std::string_view field) { return material.contains(std::string(field)); });
}

struct UnitHint {
  std::string_view pointer;
  std::string_view hint;
};

// The unit of each SI field and the slip it catches (docs/IMPACT.md, section 1).
constexpr std::array<UnitHint, 6> kUnitHints{{
    {"/material/diameter", "in m: 20 nm is 2e-08"},
    {"/material/youngs_modulus", "in Pa: 25 GPa is 2.5e10"},
    {"/material/density", "in kg/m^3: 1.7 g/cm^3 is 1700"},
    {"/material/surface_energy", "in J/m^2: 50 mJ/m^2 is 0.05"},
    {"/wall/material/youngs_modulus", "in Pa: 25 GPa is 2.5e10"},
    {"/wall/material/surface_energy", "in J/m^2: 50 mJ/m^2 is 0.05"},
}};

}  // namespace

std::optional<UnitsHint> units_hint(const Json& document) {
  if (!document.is_object() || !document.contains("material") || !document["material"].is_object()) return std::nullopt;
  const Json& material = document["material"];
  const auto units = document.find("units");
  if (units != document.end() && !units->is_string()) return std::nullopt;
  const std::string given = units == document.end() ? "" : units->get<std::string>();
  const bool reduced_material = material.contains("gamma_over_kn");
  if (given != "physical" && has_any_si_field(material) && !reduced_material) {
    const std::string read_as = given.empty() ? "is missing, so the case is in reduced units (d, m, tau)"
                                              : "is \"" + given + "\": reduced units (d, m, tau)";
    return UnitsHint{"physical",
                     {"/units", read_as + ", whose /material is gamma_over_kn and poisson_ratio; this "
                                          "/material is in SI (youngs_modulus, density, surface_energy, diameter): "
                                          "add \"units\": \"physical\""}};
  }
  if (given == "physical" && reduced_material && !has_any_si_field(material))
    return UnitsHint{"reduced",
                     {"/units",
                      "is \"physical\", whose /material is in SI (youngs_modulus, poisson_ratio, "
                      "density, surface_energy, diameter); this /material is reduced "
                      "(gamma_over_kn): leave \"units\" out or set it to \"reduced\""}};
  return std::nullopt;
}

void add_unit_hints(std::vector<SchemaViolation>& violations) {
  for (auto& violation : violations) {
    const bool out_of_range =
        violation.message.rfind("must be <", 0) == 0 || violation.message.rfind("must be >", 0) == 0;
    for (const auto& [pointer, hint] : kUnitHints)
      if (out_of_range && violation.pointer == pointer) violation.message += "; " + std::string(hint);
  }
}

}  // namespace aerobreak
