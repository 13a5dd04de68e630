#pragma once
#include <nlohmann/json.hpp>
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

// A JSON Schema (draft 2020-12) validator for the subset of the standard that the project's
// schemas (schemas/*.schema.json) use, so that the schema files are the contract and the code
// enforces exactly what they say. Implemented keywords:
//   type, enum, const, minimum, maximum, exclusiveMinimum, exclusiveMaximum, minLength, maxLength,
//   minItems, maxItems, items, required, properties, additionalProperties, allOf, anyOf, oneOf,
//   not, if/then/else, $ref (to "#/$defs/NAME" of the same document), $defs;
// annotations (not checked): $schema, $id, $comment, title, description, default, examples,
// format, deprecated, readOnly, writeOnly. A schema using any other keyword is rejected when the
// validator is built (std::invalid_argument), so nothing in a schema is silently ignored.
class JsonSchema {
 public:
  explicit JsonSchema(nlohmann::ordered_json schema);

  std::vector<SchemaViolation> validate(const nlohmann::ordered_json& document) const;
  // As validate(), and inserts the "default" of every absent property whose schema names one
  // (recursively: a defaulted object then receives its own properties' defaults). Defaults of the
  // branch an if/then/else or a oneOf selects are applied too.
  std::vector<SchemaViolation> validate_and_complete(nlohmann::ordered_json& document) const;

  const nlohmann::ordered_json& schema() const { return schema_; }

 private:
  void check(const nlohmann::ordered_json& schema, nlohmann::ordered_json& value, const std::string& pointer,
             bool complete, std::vector<SchemaViolation>& out) const;
  bool matches(const nlohmann::ordered_json& schema, const nlohmann::ordered_json& value) const;
  const nlohmann::ordered_json& resolve(const std::string& reference) const;

  nlohmann::ordered_json schema_;
};

}  // namespace aerobreak
