#pragma once
// A component of schemas/openapi.json as a JSON Schema the project's validator checks documents
// against: it and the components it refers to become $defs, their references
// "#/components/schemas/X" "#/$defs/X".
#include <fstream>
#include <set>
#include <stdexcept>
#include <string>

#include "engine/impact/json_schema.hpp"

namespace aerobreak::testing {

inline nlohmann::ordered_json schema_file(const std::string& name) {
  std::ifstream file(std::string(AEROBREAK_SOURCE_DIR) + "/schemas/" + name);
  if (!file) throw std::runtime_error("no schemas/" + name);
  return nlohmann::ordered_json::parse(file);
}

// The names of the components that `schema` refers to, added to `names` with theirs in turn.
inline void referenced_components(const nlohmann::ordered_json& components, const nlohmann::ordered_json& schema,
                                  std::set<std::string>& names) {
  const std::string prefix = "#/components/schemas/";
  if (schema.is_object())
    for (const auto& [key, value] : schema.items()) {
      if (key == "$ref" && value.is_string() && value.get<std::string>().starts_with(prefix)) {
        // The component's name: a reference may lead into it ("#/components/schemas/X/properties/...").
        const std::string path = value.get<std::string>().substr(prefix.size());
        const std::string name = path.substr(0, path.find('/'));
        if (names.insert(name).second) referenced_components(components, components.at(name), names);
      } else {
        referenced_components(components, value, names);
      }
    }
  else if (schema.is_array())
    for (const auto& value : schema) referenced_components(components, value, names);
}

// `component` with the components it refers to (directly or not) as $defs.
inline JsonSchema openapi_component(const std::string& component) {
  const auto components = schema_file("openapi.json").at("components").at("schemas");
  std::set<std::string> names{component};
  referenced_components(components, components.at(component), names);
  nlohmann::ordered_json defs = nlohmann::ordered_json::object();
  for (const auto& name : names) defs[name] = components.at(name);
  std::string text = defs.dump();
  const std::string from = "#/components/schemas/", to = "#/$defs/";
  for (auto at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return JsonSchema(
      nlohmann::ordered_json{{"$defs", nlohmann::ordered_json::parse(text)}, {"$ref", "#/$defs/" + component}});
}

}  // namespace aerobreak::testing
