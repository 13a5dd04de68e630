#pragma once
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace aerobreak {

// One reason a document fails its schema: where (a JSON pointer into the document, "" for the
// document itself) and why.
struct SchemaViolation {
  std::string pointer;
  std::string message;
};

// The JSON pointer (RFC 6901) of member `token` under `pointer`: "~" and "/" in the token escaped.
std::string pointer_child(const std::string& pointer, const std::string& token);

// "POINTER: MESSAGE" per violation, one a line; the document itself is shown as "(document)".
std::string describe(const std::vector<SchemaViolation>& violations);

// The keywords JsonSchema implements, assertions and annotations alike (see JsonSchema).
std::vector<std::string> json_schema_keywords();

// A JSON Schema (draft 2020-12) validator for the subset of the standard that the project's
// schemas (schemas/*.schema.json) use, so that the schema files are the contract and the code
// enforces exactly what they say. Implemented keywords:
//   type, enum, const, multipleOf, minimum, maximum, exclusiveMinimum, exclusiveMaximum,
//   minLength, maxLength (in Unicode code points), minItems, maxItems, items (one schema for every
//   item), required, properties, additionalProperties, allOf, anyOf, oneOf, not, if/then/else,
//   $defs, and $ref to any schema of the same document ("#" followed by a JSON pointer, RFC 6901,
//   percent-decoded as a URI fragment, RFC 3986: "#/$defs/a~1b%25" names $defs member "a/b%");
//   boolean schemas; annotations (not checked): $schema and $id (at the root only), $comment,
//   title, description, default, examples, format, deprecated, readOnly, writeOnly.
// Values are compared as JSON values (const, enum): objects whatever the order of their members,
// 1 and 1.0 as the same number.
// The schema itself is checked when the validator is built (std::invalid_argument naming the
// place): a keyword it does not implement (so that nothing in a schema is silently ignored), a
// keyword value of the wrong kind (e.g. "minimum": "x"), a $ref that does not lead to a schema of
// the document, or references that would apply to the same value without end.
class JsonSchema {
 public:
  explicit JsonSchema(nlohmann::ordered_json schema);

  std::vector<SchemaViolation> validate(const nlohmann::ordered_json& document) const;
  // As validate(), and inserts the "default" of every absent property whose schema names one
  // (recursively: a defaulted object then receives its own properties' defaults). Defaults of the
  // branch an if/then/else or a oneOf selects are applied too.
  std::vector<SchemaViolation> validate_and_complete(nlohmann::ordered_json& document) const;

  const nlohmann::ordered_json& schema() const { return compiled_->schema; }

  // The checked schema and the target of each of its references (copies of a JsonSchema share it).
  struct Compiled {
    nlohmann::ordered_json schema;
    std::map<std::string, const nlohmann::ordered_json*> references;
  };

 private:
  std::shared_ptr<const Compiled> compiled_;
};

// Checks a schema (see JsonSchema) and resolves its references; std::invalid_argument otherwise.
std::shared_ptr<const JsonSchema::Compiled> compile_json_schema(nlohmann::ordered_json schema);

// The document without the members that `violations` name, completed again with the schema's
// defaults: what the rest of a refused document looks like, so that its other problems can be
// checked and reported in the same answer. nullopt when that is no valid document either (a
// violation names a missing required member, an array item or the document itself).
std::optional<nlohmann::ordered_json> without_violating_members(const JsonSchema& schema,
                                                                nlohmann::ordered_json document,
                                                                const std::vector<SchemaViolation>& violations);

// Equality of JSON values as JSON Schema defines it (const, enum): objects equal whatever the
// order of their members, numbers by value (1 == 1.0), no equality across types (false != 0).
bool json_equal(const nlohmann::ordered_json& a, const nlohmann::ordered_json& b);

// The number of Unicode code points of UTF-8 text (minLength and maxLength count these).
std::size_t code_points(const std::string& utf8);

}  // namespace aerobreak
