#include "orchestrator/study/study_units.hpp"

namespace aerobreak {

nlohmann::ordered_json units_json(const std::string& system) {
  if (system == "physical")
    return {{"system", system}, {"length", "m"}, {"mass", "kg"}, {"time", "s"}, {"speed", "m/s"}, {"energy", "J"}};
  if (system == "reduced")
    return {{"system", system}, {"length", "d"},    {"mass", "m"},
            {"time", "tau"},    {"speed", "d/tau"}, {"energy", "k_n d^2"}};
  return {{"system", system}, {"length", nullptr}, {"mass", nullptr},
          {"time", nullptr},  {"speed", nullptr},  {"energy", nullptr}};
}

std::string case_unit_system(const nlohmann::ordered_json& case_document) {
  const auto units = case_document.find("units");
  return units != case_document.end() && units->is_string() ? units->get<std::string>() : "reduced";
}

std::string study_unit_system(const nlohmann::ordered_json& study_document) {
  const auto axes = study_document.find("axes");
  if (axes != study_document.end() && axes->is_object() && axes->contains("/units")) return "mixed";
  const auto base = study_document.find("base");
  return base != study_document.end() && base->is_object() ? case_unit_system(*base) : "reduced";
}

}  // namespace aerobreak
