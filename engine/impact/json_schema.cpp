#include "engine/impact/json_schema.hpp"

#include <cmath>
#include <cstdlib>
#include <functional>
#include <cstdio>
#include <set>
#include <stdexcept>

namespace aerobreak {
namespace {

using Json = nlohmann::ordered_json;

const std::set<std::string>& annotation_keywords() {
  static const std::set<std::string> keywords{"$schema", "$id",     "$comment",   "title",    "description",
                                              "default", "examples", "format",    "deprecated", "readOnly",
                                              "writeOnly"};
  return keywords;
}

const std::set<std::string>& assertion_keywords() {
  static const std::set<std::string> keywords{
      "type",     "enum",     "const",    "minimum",    "maximum",    "exclusiveMinimum", "exclusiveMaximum",
      "minLength", "maxLength", "minItems", "maxItems", "items",      "required",         "properties",
      "additionalProperties", "allOf", "anyOf", "oneOf", "not", "if", "then", "else", "$ref", "$defs"};
  return keywords;
}


std::string child(const std::string& pointer, const std::string& token) { return pointer_child(pointer, token); }

std::string type_name(const Json& v) {
  switch (v.type()) {
    case Json::value_t::null: return "null";
    case Json::value_t::boolean: return "boolean";
    case Json::value_t::string: return "string";
    case Json::value_t::array: return "array";
    case Json::value_t::object: return "object";
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned: return "integer";
    case Json::value_t::number_float: return "number";
    default: return "unknown";
  }
}

bool has_type(const Json& v, const std::string& type) {
  if (type == "null") return v.is_null();
  if (type == "boolean") return v.is_boolean();
  if (type == "string") return v.is_string();
  if (type == "array") return v.is_array();
  if (type == "object") return v.is_object();
  if (type == "number") return v.is_number();
  if (type == "integer") {
    if (v.is_number_integer()) return true;
    if (!v.is_number_float()) return false;
    const double x = v.get<double>();
    return std::isfinite(x) && std::floor(x) == x;
  }
  throw std::invalid_argument("JSON schema: unknown type \"" + type + "\"");
}

std::string number_text(double x) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  // Prefer the short form when it reads back to the same number.
  char shorter[64];
  std::snprintf(shorter, sizeof shorter, "%g", x);
  return std::strtod(shorter, nullptr) == x ? shorter : buffer;
}

std::string shown(const Json& v) {
  std::string text = v.dump();
  if (text.size() <= 60) return text;
  // Cut before a UTF-8 continuation byte's character, never inside it.
  std::size_t cut = 57;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
  return text.substr(0, cut) + "...";
}

// Rejects keywords the validator does not implement, so a schema cannot ask for a check that is
// then silently skipped.
void check_keywords(const Json& schema, const std::string& where) {
  if (schema.is_boolean()) return;
  if (!schema.is_object()) throw std::invalid_argument("JSON schema at " + where + ": a schema must be an object or a boolean");
  for (const auto& [key, value] : schema.items()) {
    if (annotation_keywords().count(key)) continue;
    if (!assertion_keywords().count(key))
      throw std::invalid_argument("JSON schema at " + where + ": keyword \"" + key + "\" is not implemented");
    if (key == "properties" || key == "$defs") {
      for (const auto& [name, sub] : value.items()) check_keywords(sub, where + "/" + key + "/" + name);
    } else if (key == "items" || key == "additionalProperties" || key == "not" || key == "if" || key == "then" ||
               key == "else") {
      check_keywords(value, where + "/" + key);
    } else if (key == "allOf" || key == "anyOf" || key == "oneOf") {
      if (!value.is_array() || value.empty())
        throw std::invalid_argument("JSON schema at " + where + ": " + key + " must be a non-empty array");
      for (std::size_t k = 0; k < value.size(); ++k) check_keywords(value[k], where + "/" + key + "/" + std::to_string(k));
    } else if (key == "$ref") {
      if (!value.is_string() || value.get<std::string>().rfind("#/$defs/", 0) != 0)
        throw std::invalid_argument("JSON schema at " + where + ": only \"#/$defs/NAME\" references are implemented");
    }
  }
}

}  // namespace

std::string describe(const std::vector<SchemaViolation>& violations) {
  std::string text;
  for (const auto& v : violations) {
    if (!text.empty()) text += "\n";
    text += (v.pointer.empty() ? std::string("(document)") : v.pointer) + ": " + v.message;
  }
  return text;
}

JsonSchema::JsonSchema(nlohmann::ordered_json schema) : schema_(std::move(schema)) {
  check_keywords(schema_, "#");
  // Every reference must resolve now rather than at the first document that reaches it.
  const std::function<void(const Json&)> visit = [&](const Json& node) {
    if (node.is_object()) {
      if (node.contains("$ref") && node["$ref"].is_string()) resolve(node["$ref"].get<std::string>());
      for (const auto& [key, value] : node.items())
        if (key != "default" && key != "examples" && key != "enum" && key != "const") visit(value);
    } else if (node.is_array()) {
      for (const auto& value : node) visit(value);
    }
  };
  visit(schema_);
}

const nlohmann::ordered_json& JsonSchema::resolve(const std::string& reference) const {
  const std::string name = reference.substr(std::string("#/$defs/").size());
  if (!schema_.contains("$defs") || !schema_["$defs"].contains(name))
    throw std::invalid_argument("JSON schema: unresolved reference " + reference);
  return schema_["$defs"][name];
}

std::vector<SchemaViolation> JsonSchema::validate(const nlohmann::ordered_json& document) const {
  Json copy = document;
  std::vector<SchemaViolation> out;
  check(schema_, copy, "", false, out);
  return out;
}

std::vector<SchemaViolation> JsonSchema::validate_and_complete(nlohmann::ordered_json& document) const {
  std::vector<SchemaViolation> out;
  check(schema_, document, "", true, out);
  return out;
}

bool JsonSchema::matches(const nlohmann::ordered_json& schema, const nlohmann::ordered_json& value) const {
  Json copy = value;
  std::vector<SchemaViolation> out;
  check(schema, copy, "", false, out);
  return out.empty();
}

void JsonSchema::check(const nlohmann::ordered_json& schema, nlohmann::ordered_json& value, const std::string& pointer,
                       bool complete, std::vector<SchemaViolation>& out) const {
  if (schema.is_boolean()) {
    if (!schema.get<bool>()) out.push_back({pointer, "is not allowed here"});
    return;
  }
  auto fail = [&](const std::string& message) { out.push_back({pointer, message}); };

  if (schema.contains("$ref")) check(resolve(schema["$ref"].get<std::string>()), value, pointer, complete, out);

  if (schema.contains("type")) {
    const Json& type = schema["type"];
    bool ok = false;
    std::string wanted;
    if (type.is_string()) {
      ok = has_type(value, type.get<std::string>());
      wanted = type.get<std::string>();
    } else {
      for (const auto& t : type) {
        ok = ok || has_type(value, t.get<std::string>());
        wanted += (wanted.empty() ? "" : " or ") + t.get<std::string>();
      }
    }
    if (!ok) {
      const bool vowel = std::string("aeiou").find(wanted[0]) != std::string::npos;
      fail(std::string("must be ") + (vowel ? "an " : "a ") + wanted + " (got " + type_name(value) + " " +
           shown(value) + ")");
      return;  // the remaining keywords would only repeat the type error
    }
  }

  if (schema.contains("enum")) {
    bool found = false;
    std::string allowed;
    for (const auto& option : schema["enum"]) {
      found = found || option == value;
      allowed += (allowed.empty() ? "" : ", ") + option.dump();
    }
    if (!found) fail("must be one of " + allowed + " (got " + shown(value) + ")");
  }
  if (schema.contains("const") && schema["const"] != value)
    fail("must be " + schema["const"].dump() + " (got " + shown(value) + ")");

  if (value.is_number()) {
    const double x = value.get<double>();
    if (!std::isfinite(x)) fail("must be a finite number");
    if (schema.contains("minimum") && !(x >= schema["minimum"].get<double>()))
      fail("must be >= " + number_text(schema["minimum"].get<double>()) + " (got " + number_text(x) + ")");
    if (schema.contains("maximum") && !(x <= schema["maximum"].get<double>()))
      fail("must be <= " + number_text(schema["maximum"].get<double>()) + " (got " + number_text(x) + ")");
    if (schema.contains("exclusiveMinimum") && !(x > schema["exclusiveMinimum"].get<double>()))
      fail("must be > " + number_text(schema["exclusiveMinimum"].get<double>()) + " (got " + number_text(x) + ")");
    if (schema.contains("exclusiveMaximum") && !(x < schema["exclusiveMaximum"].get<double>()))
      fail("must be < " + number_text(schema["exclusiveMaximum"].get<double>()) + " (got " + number_text(x) + ")");
  }

  if (value.is_string()) {
    const std::size_t length = value.get<std::string>().size();
    if (schema.contains("minLength") && length < schema["minLength"].get<std::size_t>())
      fail("must have at least " + std::to_string(schema["minLength"].get<std::size_t>()) + " characters");
    if (schema.contains("maxLength") && length > schema["maxLength"].get<std::size_t>())
      fail("must have at most " + std::to_string(schema["maxLength"].get<std::size_t>()) + " characters");
  }

  if (value.is_array()) {
    if (schema.contains("minItems") && value.size() < schema["minItems"].get<std::size_t>())
      fail("must have at least " + std::to_string(schema["minItems"].get<std::size_t>()) + " items (got " +
           std::to_string(value.size()) + ")");
    if (schema.contains("maxItems") && value.size() > schema["maxItems"].get<std::size_t>())
      fail("must have at most " + std::to_string(schema["maxItems"].get<std::size_t>()) + " items (got " +
           std::to_string(value.size()) + ")");
    if (schema.contains("items"))
      for (std::size_t k = 0; k < value.size(); ++k)
        check(schema["items"], value[k], child(pointer, std::to_string(k)), complete, out);
  }

  if (value.is_object()) {
    if (schema.contains("required"))
      for (const auto& name : schema["required"])
        if (!value.contains(name.get<std::string>()))
          out.push_back({child(pointer, name.get<std::string>()), "is required"});
    if (schema.contains("properties")) {
      for (const auto& [name, sub] : schema["properties"].items()) {
        if (complete && !value.contains(name) && sub.is_object() && sub.contains("default")) value[name] = sub["default"];
        if (value.contains(name)) check(sub, value[name], child(pointer, name), complete, out);
      }
    }
    if (schema.contains("additionalProperties")) {
      const Json& extra = schema["additionalProperties"];
      const Json known = schema.contains("properties") ? schema["properties"] : Json::object();
      for (auto& [name, sub_value] : value.items()) {
        if (known.contains(name)) continue;
        if (extra.is_boolean() && !extra.get<bool>()) {
          std::string allowed;
          for (const auto& [k, unused] : known.items()) allowed += (allowed.empty() ? "" : ", ") + k;
          out.push_back({child(pointer, name), "is not a recognised field" +
                                                   (allowed.empty() ? std::string() : " (allowed here: " + allowed + ")")});
        } else {
          check(extra, sub_value, child(pointer, name), complete, out);
        }
      }
    }
  }

  if (schema.contains("allOf"))
    for (const auto& sub : schema["allOf"]) check(sub, value, pointer, complete, out);

  auto first_violation = [&](const Json& sub) {
    Json copy = value;
    std::vector<SchemaViolation> inner;
    check(sub, copy, pointer, false, inner);
    return inner.empty() ? std::string() : describe({inner.front()});
  };
  if (schema.contains("anyOf")) {
    const Json& options = schema["anyOf"];
    const Json* chosen = nullptr;
    for (const auto& sub : options)
      if (matches(sub, value)) {
        chosen = &sub;
        break;
      }
    if (chosen) {
      if (complete) check(*chosen, value, pointer, true, out);
    } else {
      std::string why;
      for (std::size_t k = 0; k < options.size(); ++k)
        why += (k ? "; " : "") + std::to_string(k + 1) + ": " + first_violation(options[k]);
      fail("must match at least one of " + std::to_string(options.size()) + " alternatives, matches none (" + why + ")");
    }
  }
  if (schema.contains("oneOf")) {
    const Json& options = schema["oneOf"];
    std::vector<std::size_t> matching;
    for (std::size_t k = 0; k < options.size(); ++k)
      if (matches(options[k], value)) matching.push_back(k);
    if (matching.size() == 1) {
      if (complete) check(options[matching.front()], value, pointer, true, out);
    } else if (matching.empty()) {
      std::string why;
      for (std::size_t k = 0; k < options.size(); ++k)
        why += (k ? "; " : "") + std::to_string(k + 1) + ": " + first_violation(options[k]);
      fail("must match exactly one of " + std::to_string(options.size()) + " alternatives, matches none (" + why + ")");
    } else {
      std::string which;
      for (std::size_t k : matching) which += (which.empty() ? "" : " and ") + std::to_string(k + 1);
      fail("must match exactly one of " + std::to_string(options.size()) + " alternatives, matches " + which);
    }
  }
  if (schema.contains("not") && matches(schema["not"], value)) fail("matches a form that is not allowed here");

  if (schema.contains("if")) {
    if (matches(schema["if"], value)) {
      if (schema.contains("then")) check(schema["then"], value, pointer, complete, out);
    } else if (schema.contains("else")) {
      check(schema["else"], value, pointer, complete, out);
    }
  }
}

std::string pointer_child(const std::string& pointer, const std::string& token) {
  std::string out = pointer + "/";
  for (char c : token) {
    if (c == '~')
      out += "~0";
    else if (c == '/')
      out += "~1";
    else
      out += c;
  }
  return out;
}

}  // namespace aerobreak
