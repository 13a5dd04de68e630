// Checking a schema when it is loaded (json_schema.hpp): every keyword known and its value of the
// right kind, every reference resolved to a schema of the document, no reference loop that would
// apply to one value without end.
#include <cctype>
#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>

#include "engine/impact/json_schema.hpp"

namespace aerobreak {
namespace {

using Json = nlohmann::ordered_json;

// What a keyword's value must be (draft 2020-12, "JSON Schema Validation" and "Core").
enum class KeywordValue {
  schema,           // a schema (an object or a boolean)
  schema_map,       // an object whose members are schemas
  schema_list,      // a non-empty array of schemas
  reference,        // a string: "#" and a JSON pointer to a schema of this document
  type_names,       // a type name or a non-empty array of distinct type names
  value_list,       // a non-empty array of any values
  name_list,        // an array of distinct strings
  number,           // a finite number
  positive_number,  // a finite number > 0
  count,            // a non-negative integer
  any,              // any value
  list,             // an array
  text,             // a string
  flag,             // a boolean
};

const std::map<std::string, KeywordValue>& keyword_values() {
  using enum KeywordValue;
  static const std::map<std::string, KeywordValue> table{{"type", type_names},
                                                         {"enum", value_list},
                                                         {"const", any},
                                                         {"multipleOf", positive_number},
                                                         {"minimum", number},
                                                         {"maximum", number},
                                                         {"exclusiveMinimum", number},
                                                         {"exclusiveMaximum", number},
                                                         {"minLength", count},
                                                         {"maxLength", count},
                                                         {"minItems", count},
                                                         {"maxItems", count},
                                                         {"items", schema},
                                                         {"required", name_list},
                                                         {"properties", schema_map},
                                                         {"additionalProperties", schema},
                                                         {"allOf", schema_list},
                                                         {"anyOf", schema_list},
                                                         {"oneOf", schema_list},
                                                         {"not", schema},
                                                         {"if", schema},
                                                         {"then", schema},
                                                         {"else", schema},
                                                         {"$ref", reference},
                                                         {"$defs", schema_map},
                                                         // Annotations: accepted, not checked against documents.
                                                         {"$schema", text},
                                                         {"$id", text},
                                                         {"$comment", text},
                                                         {"title", text},
                                                         {"description", text},
                                                         {"default", any},
                                                         {"examples", list},
                                                         {"format", text},
                                                         {"deprecated", flag},
                                                         {"readOnly", flag},
                                                         {"writeOnly", flag}};
  return table;
}

bool is_schema(const Json& value) { return value.is_object() || value.is_boolean(); }

bool is_count(const Json& value) {
  if (value.is_number_unsigned()) return true;
  if (value.is_number_integer()) return value.get<std::int64_t>() >= 0;
  if (!value.is_number_float()) return false;
  const double x = value.get<double>();
  return std::isfinite(x) && x >= 0 && std::floor(x) == x;
}

bool is_type_name(const Json& value) {
  static const std::set<std::string> names{"null", "boolean", "object", "array", "number", "string", "integer"};
  return value.is_string() && names.count(value.get<std::string>());
}

bool distinct_strings(const Json& list, bool (*accepted)(const Json&)) {
  std::set<std::string> seen;
  for (const auto& item : list)
    if (!accepted(item) || !seen.insert(item.get<std::string>()).second) return false;
  return true;
}

// Why `value` is not what `kind` asks for; empty when it is.
std::string value_problem(KeywordValue kind, const Json& value) {
  using enum KeywordValue;
  const auto is_string = [](const Json& v) { return v.is_string(); };
  switch (kind) {
    case schema:
      return is_schema(value) ? "" : "must be a schema (an object or a boolean)";
    case schema_map:
      return value.is_object() ? "" : "must be an object of schemas";
    case schema_list:
      return value.is_array() && !value.empty() ? "" : "must be a non-empty array of schemas";
    case reference:
      return value.is_string() ? "" : "must be a string";
    case type_names:
      return is_type_name(value) || (value.is_array() && !value.empty() && distinct_strings(value, is_type_name))
                 ? ""
                 : "must be a type name (null, boolean, object, array, number, string, integer) or a non-empty "
                   "array of distinct type names";
    case value_list:
      return value.is_array() && !value.empty() ? "" : "must be a non-empty array";
    case name_list:
      return value.is_array() && distinct_strings(value, is_string) ? "" : "must be an array of distinct strings";
    case number:
      return value.is_number() && std::isfinite(value.get<double>()) ? "" : "must be a finite number";
    case positive_number:
      return value.is_number() && std::isfinite(value.get<double>()) && value.get<double>() > 0
                 ? ""
                 : "must be a number > 0";
    case count:
      return is_count(value) ? "" : "must be a non-negative integer";
    case any:
      return "";
    case list:
      return value.is_array() ? "" : "must be an array";
    case text:
      return value.is_string() ? "" : "must be a string";
    case flag:
      return value.is_boolean() ? "" : "must be a boolean";
  }
  return "";
}

// Decodes the percent-encoding of a URI fragment (RFC 3986, 2.1); nullopt when malformed.
std::optional<std::string> percent_decoded(const std::string& text) {
  std::string out;
  for (std::size_t k = 0; k < text.size(); ++k) {
    if (text[k] != '%') {
      out += text[k];
      continue;
    }
    if (k + 2 >= text.size()) return std::nullopt;
    const std::string digits = text.substr(k + 1, 2);
    if (!std::isxdigit(static_cast<unsigned char>(digits[0])) || !std::isxdigit(static_cast<unsigned char>(digits[1])))
      return std::nullopt;
    out += static_cast<char>(std::stoi(digits, nullptr, 16));
    k += 2;
  }
  return out;
}

// A JSON pointer (RFC 6901): empty, or "/"-separated tokens in which "~" is followed by 0 or 1.
bool well_formed_pointer(const std::string& pointer) {
  if (!pointer.empty() && pointer.front() != '/') return false;
  for (std::size_t k = 0; k < pointer.size(); ++k)
    if (pointer[k] == '~' && (k + 1 == pointer.size() || (pointer[k + 1] != '0' && pointer[k + 1] != '1')))
      return false;
  return true;
}

// Walks the schema positions of a schema document, checking each keyword, and remembers every
// schema's place (a JSON pointer), the places each applies to the same value as itself (in-place
// applicators and references), and the references to resolve.
class SchemaWalk {
 public:
  explicit SchemaWalk(const Json& root) : root_(root) { visit(root, ""); }

  // Resolves each reference to the schema it names; std::invalid_argument when one does not.
  std::map<std::string, const Json*> resolve_references() const {
    std::map<std::string, const Json*> targets;
    for (const auto& [reference, where] : references_) {
      const std::string pointer = target_pointer(reference, where);
      targets[reference] = &root_.at(Json::json_pointer(pointer));
    }
    return targets;
  }

  // Refuses references that lead back to a schema applying to the same value (e.g. a $ref to
  // itself, or two $defs referring to each other in allOf): validation would never end.
  void refuse_endless_references() const {
    std::map<std::string, int> state;  // 1: on the current path, 2: done
    const std::function<void(const std::string&)> visit_place = [&](const std::string& place) {
      state[place] = 1;
      const auto next = in_place_.find(place);
      if (next != in_place_.end()) {
        for (const auto& target : next->second) {
          if (state[target] == 1)
            fail(place,
                 "references lead back here without going into a member or item: "
                 "validation would never end");
          if (state[target] == 0) visit_place(target);
        }
      }
      state[place] = 2;
    };
    for (const auto& place : places_)
      if (state[place] == 0) visit_place(place);
  }

 private:
  [[noreturn]] static void fail(const std::string& where, const std::string& message) {
    throw std::invalid_argument("JSON schema at #" + where + ": " + message);
  }

  std::string target_pointer(const std::string& reference, const std::string& where) const {
    if (reference.empty() || reference.front() != '#')
      fail(where, "$ref \"" + reference + "\" is not implemented: only references within the document (\"#...\")");
    const auto pointer = percent_decoded(reference.substr(1));
    if (!pointer || !well_formed_pointer(*pointer))
      fail(where, "$ref \"" + reference + "\" is not a JSON pointer (RFC 6901) after its percent-decoding");
    if (!places_.count(*pointer)) fail(where, "unresolved reference " + reference + " (no schema there)");
    return *pointer;
  }

  void visit(const Json& schema, const std::string& where) {
    places_.insert(where);
    if (schema.is_boolean()) return;
    if (!schema.is_object()) fail(where, "a schema must be an object or a boolean");
    for (const auto& [key, value] : schema.items()) check_keyword(key, value, where);
  }

  void check_keyword(const std::string& key, const Json& value, const std::string& where) {
    const auto found = keyword_values().find(key);
    if (found == keyword_values().end()) fail(where, "keyword \"" + key + "\" is not implemented");
    if (const std::string problem = value_problem(found->second, value); !problem.empty())
      fail(where, "\"" + key + "\" " + problem + " (got " + value.dump() + ")");
    if ((key == "$id" || key == "$schema") && !where.empty())
      fail(where, "\"" + key + "\" is implemented at the root of the schema only");
    const std::string place = pointer_child(where, key);
    const bool in_place = key != "properties" && key != "additionalProperties" && key != "items" && key != "$defs";
    switch (found->second) {
      case KeywordValue::schema:
        if (in_place) in_place_[where].push_back(place);
        visit(value, place);
        break;
      case KeywordValue::schema_map:
        for (const auto& [name, sub] : value.items()) visit(sub, pointer_child(place, name));
        break;
      case KeywordValue::schema_list:
        for (std::size_t k = 0; k < value.size(); ++k) {
          in_place_[where].push_back(pointer_child(place, std::to_string(k)));
          visit(value[k], pointer_child(place, std::to_string(k)));
        }
        break;
      case KeywordValue::reference:
        references_.emplace(value.get<std::string>(), where);
        in_place_[where].push_back(target_place(value.get<std::string>()));
        break;
      default:
        break;
    }
  }

  // The place a reference names, as far as it can be read now (checked in resolve_references).
  static std::string target_place(const std::string& reference) {
    return percent_decoded(reference.substr(std::min<std::size_t>(1, reference.size()))).value_or("");
  }

  const Json& root_;
  std::set<std::string> places_;
  std::map<std::string, std::vector<std::string>> in_place_;
  std::map<std::string, std::string> references_;  // reference -> a place that uses it
};

}  // namespace

std::vector<std::string> json_schema_keywords() {
  std::vector<std::string> names;
  for (const auto& [name, unused] : keyword_values()) names.push_back(name);
  return names;
}

std::shared_ptr<const JsonSchema::Compiled> compile_json_schema(nlohmann::ordered_json schema) {
  auto compiled = std::make_shared<JsonSchema::Compiled>();
  compiled->schema = std::move(schema);
  const SchemaWalk walk(compiled->schema);
  compiled->references = walk.resolve_references();
  walk.refuse_endless_references();
  return compiled;
}

}  // namespace aerobreak
