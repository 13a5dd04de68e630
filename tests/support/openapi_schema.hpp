#pragma once
// A part of schemas/openapi.json as a JSON Schema that the project's validator (draft 2020-12)
// checks documents against: the components it reaches become $defs, their references
// "#/components/schemas/X..." "#/$defs/X...".
#include <fstream>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>

#include "engine/impact/json_schema.hpp"

namespace aerobreak::testing {

inline nlohmann::ordered_json schema_file(const std::string& name) {
  std::ifstream file(std::string(AEROBREAK_SOURCE_DIR) + "/schemas/" + name);
  if (!file) throw std::runtime_error("no schemas/" + name);
  return nlohmann::ordered_json::parse(file);
}

// `node` with every "#/components/schemas/X..." reference turned into "#/$defs/X...", collecting
// the X (a reference may lead into a component: "#/components/schemas/X/properties/...").
inline void rewrite_references(nlohmann::ordered_json& node, std::set<std::string>& named) {
  constexpr std::string_view kPrefix = "#/components/schemas/";
  if (node.is_object()) {
    for (auto& [key, value] : node.items()) {
      if (key == "$ref" && value.is_string() && value.get<std::string>().starts_with(kPrefix)) {
        const std::string path = value.get<std::string>().substr(kPrefix.size());
        named.insert(path.substr(0, path.find('/')));
        value = "#/$defs/" + path;
      } else {
        rewrite_references(value, named);
      }
    }
  } else if (node.is_array()) {
    for (auto& item : node) rewrite_references(item, named);
  }
}

// `schema` (a part of the OpenAPI `description`) with the components it reaches under $defs.
inline JsonSchema openapi_schema(const nlohmann::ordered_json& description, nlohmann::ordered_json schema) {
  std::set<std::string> named, done;
  rewrite_references(schema, named);
  nlohmann::ordered_json definitions = nlohmann::ordered_json::object();
  while (named.size() > done.size()) {
    for (const auto& name : std::set<std::string>(named)) {
      if (!done.insert(name).second) continue;
      auto component = description.at("components").at("schemas").at(name);
      rewrite_references(component, named);
      definitions[name] = std::move(component);
    }
  }
  schema["$defs"] = std::move(definitions);
  return JsonSchema(std::move(schema));
}

// The component `name` of schemas/openapi.json.
inline JsonSchema openapi_component(const std::string& name) {
  return openapi_schema(schema_file("openapi.json"), {{"$ref", "#/components/schemas/" + name}});
}

}  // namespace aerobreak::testing
