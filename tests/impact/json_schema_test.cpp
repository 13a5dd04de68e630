// JsonSchema where the JSON-Schema-Test-Suite in Debian (draft 7) does not reach: what only draft
// 2020-12 defines ($defs, $ref applied together with the keywords beside it, items as one schema),
// references with escaped names, the checks of a schema when it is loaded, and the comparisons
// (const, enum, lengths) the validator once got wrong.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "engine/impact/json_schema.hpp"

using namespace aerobreak;
using Json = nlohmann::ordered_json;
using Catch::Matchers::Contains;

namespace {

bool valid(const Json& schema, const Json& document) { return JsonSchema(schema).validate(document).empty(); }

// The message of the std::invalid_argument that loading `schema` throws; fails when it loads.
std::string load_error(const Json& schema) {
  try {
    JsonSchema loaded(schema);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  FAIL("the schema loaded: " << schema.dump());
  return {};
}

}  // namespace

TEST_CASE("$ref resolves $defs names with JSON pointer escapes (~0, ~1) and percent-encoding") {
  // The suite's "escaped pointer ref" (draft 7, names outside $defs) with the names under $defs.
  const Json schema = Json::parse(R"({
    "$defs": {"tilda~field": {"type": "integer"}, "slash/field": {"type": "integer"},
              "percent%field": {"type": "integer"}, "space field": {"type": "integer"}, "é": {"type": "integer"}},
    "properties": {"tilda": {"$ref": "#/$defs/tilda~0field"}, "slash": {"$ref": "#/$defs/slash~1field"},
                   "percent": {"$ref": "#/$defs/percent%25field"}, "space": {"$ref": "#/$defs/space%20field"},
                   "encoded_slash": {"$ref": "#/$defs/slash%7E1field"}, "accent": {"$ref": "#/$defs/%C3%A9"}}})");
  for (const char* name : {"tilda", "slash", "percent", "space", "encoded_slash", "accent"}) {
    INFO(name);
    CHECK(valid(schema, {{name, 123}}));
    CHECK_FALSE(valid(schema, {{name, "aoeu"}}));
  }
}

TEST_CASE("$ref applies together with the keywords beside it (draft 2020-12, unlike draft 7)") {
  const Json schema = Json::parse(R"({"$defs": {"reffed": {"type": "array"}},
                                      "properties": {"foo": {"$ref": "#/$defs/reffed", "maxItems": 2}}})");
  CHECK(valid(schema, {{"foo", Json::array({1, 2})}}));
  CHECK_FALSE(valid(schema, {{"foo", Json::array({1, 2, 3})}}));
  CHECK_FALSE(valid(schema, {{"foo", "string"}}));
}

TEST_CASE("$defs: nested references, boolean schemas, references from $defs to the root") {
  const Json nested = Json::parse(R"({"$defs": {"a": {"type": "integer"}, "b": {"$ref": "#/$defs/a"},
                                      "c": {"$ref": "#/$defs/b"}}, "$ref": "#/$defs/c"})");
  CHECK(valid(nested, 5));
  CHECK_FALSE(valid(nested, "a"));
  CHECK(valid(Json::parse(R"({"$defs": {"yes": true}, "$ref": "#/$defs/yes"})"), "anything"));
  CHECK_FALSE(valid(Json::parse(R"({"$defs": {"no": false}, "$ref": "#/$defs/no"})"), "anything"));
  // A tree: each node's children are trees.
  const Json tree = Json::parse(R"({"$defs": {"node": {"type": "object", "additionalProperties": false,
      "properties": {"value": {"type": "integer"}, "children": {"type": "array", "items": {"$ref": "#"}}}}},
      "$ref": "#/$defs/node"})");
  CHECK(valid(tree, Json::parse(R"({"value": 1, "children": [{"value": 2, "children": [{"value": 3}]}]})")));
  CHECK_FALSE(valid(tree, Json::parse(R"({"value": 1, "children": [{"value": 2, "children": [{"value": "x"}]}]})")));
}

TEST_CASE("items is one schema for every item (draft 2020-12), the draft-7 array form is refused") {
  const Json schema{{"items", {{"type", "integer"}}}};
  CHECK(valid(schema, Json::array({1, 2, 3})));
  CHECK_FALSE(valid(schema, Json::array({1, "x"})));
  CHECK_THAT(load_error(Json::parse(R"({"items": [{"type": "integer"}]})")), Contains("\"items\" must be a schema"));
}

TEST_CASE("const and enum compare objects as JSON values, whatever the order of their members") {
  const Json schema = Json::parse(R"({"const": {"a": 1, "b": {"c": [1, {"d": 2, "e": 3}]}}})");
  CHECK(valid(schema, Json::parse(R"({"b": {"c": [1, {"e": 3, "d": 2}]}, "a": 1})")));
  CHECK(valid(schema, Json::parse(R"({"b": {"c": [1.0, {"e": 3, "d": 2.0}]}, "a": 1})")));
  CHECK_FALSE(valid(schema, Json::parse(R"({"b": {"c": [{"e": 3, "d": 2}, 1]}, "a": 1})")));  // arrays keep order
  CHECK_FALSE(valid(schema, Json::parse(R"({"a": 1, "b": {"c": [1, {"d": 2, "e": 3, "f": 4}]}})")));
  const Json options = Json::parse(R"({"enum": [{"x": 1, "y": 2}, false]})");
  CHECK(valid(options, Json::parse(R"({"y": 2, "x": 1})")));
  CHECK_FALSE(valid(options, 0));  // false is not 0
  CHECK(json_equal(Json(1), Json(1.0)));
  CHECK_FALSE(json_equal(Json(-1), Json(std::uint64_t{18446744073709551615u})));
}

TEST_CASE("minLength and maxLength count Unicode code points, not bytes") {
  CHECK(code_points("a\xc3\xa9\xe2\x82\xac\xf0\x9f\x92\xa9") == 4);  // a, e-acute (2 bytes), euro (3), U+1F4A9 (4)
  CHECK(valid({{"maxLength", 1}}, "\xc3\xa9"));
  CHECK(valid({{"maxLength", 1}}, "\xf0\x9f\x92\xa9"));
  CHECK_FALSE(valid({{"minLength", 2}}, "\xf0\x9f\x92\xa9"));
  CHECK(valid({{"minLength", 2}, {"maxLength", 2}}, "\xe2\x82\xac\xc3\xa9"));
  const auto violations = JsonSchema(Json{{"maxLength", 3}}).validate("\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9");
  REQUIRE(violations.size() == 1);
  CHECK_THAT(violations.front().message, Contains("at most 3 characters (got 4)"));
}

TEST_CASE("multipleOf: integers exactly, decimal fractions within rounding") {
  CHECK(valid({{"multipleOf", 0.1}}, 0.3));
  CHECK(valid({{"multipleOf", 0.01}}, 19.99));
  CHECK_FALSE(valid({{"multipleOf", 0.1}}, 0.35));
  CHECK(valid({{"multipleOf", 3}}, std::uint64_t{18446744073709551615u}));
  // -(2^63 - 1) = -7 x 1317624576693539401, beyond a double's 53 bits: only exact arithmetic tells.
  CHECK(valid({{"multipleOf", 7}}, std::int64_t{-9223372036854775807}));
  CHECK_FALSE(valid({{"multipleOf", 11}}, std::int64_t{-9223372036854775807}));
  CHECK_FALSE(valid({{"multipleOf", 1e-300}}, 1e300));  // the quotient overflows: not a finite multiple
}

TEST_CASE("a keyword value of the wrong kind is refused when the schema is loaded, naming the place") {
  const std::vector<std::pair<const char*, const char*>> cases{
      {R"({"minimum": "x"})", "\"minimum\" must be a finite number"},
      {R"({"properties": {"a": {"exclusiveMaximum": true}}})", "#/properties/a: \"exclusiveMaximum\""},
      {R"({"maxLength": -1})", "\"maxLength\" must be a non-negative integer"},
      {R"({"minItems": 1.5})", "\"minItems\" must be a non-negative integer"},
      {R"({"multipleOf": 0})", "\"multipleOf\" must be a number > 0"},
      {R"({"type": "float"})", "\"type\" must be a type name"},
      {R"({"type": ["string", "string"]})", "distinct type names"},
      {R"({"type": []})", "\"type\" must be a type name"},
      {R"({"enum": []})", "\"enum\" must be a non-empty array"},
      {R"({"enum": 3})", "\"enum\" must be a non-empty array"},
      {R"({"required": ["a", "a"]})", "\"required\" must be an array of distinct strings"},
      {R"({"required": "a"})", "\"required\" must be an array of distinct strings"},
      {R"({"properties": []})", "\"properties\" must be an object of schemas"},
      {R"({"properties": {"a": 3}})", "#/properties/a: a schema must be an object or a boolean"},
      {R"({"$defs": {"a/b": {"minimum": "x"}}})", "#/$defs/a~1b: \"minimum\""},
      {R"({"allOf": []})", "\"allOf\" must be a non-empty array of schemas"},
      {R"({"anyOf": [{}, 3]})", "#/anyOf/1: a schema must be an object or a boolean"},
      {R"({"not": 3})", "\"not\" must be a schema"},
      {R"({"title": 1})", "\"title\" must be a string"},
      {R"({"deprecated": "yes"})", "\"deprecated\" must be a boolean"},
      {R"({"examples": 1})", "\"examples\" must be an array"},
      {R"({"properties": {"a": {"$id": "urn:a"}}})", "\"$id\" is implemented at the root of the schema only"},
      {R"({"pattern": "^a"})", "keyword \"pattern\" is not implemented"},
  };
  for (const auto& [schema, message] : cases) {
    INFO(schema);
    CHECK_THAT(load_error(Json::parse(schema)), Contains(message));
  }
}

TEST_CASE("a reference that leads nowhere, or round in a circle on the same value, is refused when loaded") {
  const std::vector<std::pair<const char*, const char*>> cases{
      {R"({"$ref": 3})", "\"$ref\" must be a string"},
      {R"({"$ref": "#/$defs/missing"})", "unresolved reference #/$defs/missing"},
      {R"({"$ref": "other.json#/$defs/a"})", "only references within the document"},
      {R"({"$defs": {"a": {}}, "$ref": "#/$defs/a%2"})", "is not a JSON pointer"},
      {R"({"$defs": {"a": {}}, "$ref": "#/$defs/a~2"})", "is not a JSON pointer"},
      {R"({"$defs": {"a": {}}, "$ref": "#$defs/a"})", "is not a JSON pointer"},
      // A value that is not a schema of the document: a default, not a place keywords put schemas.
      {R"({"properties": {"a": {"default": {"type": "string"}}}, "$ref": "#/properties/a/default"})",
       "unresolved reference"},
      {R"({"$ref": "#"})", "validation would never end"},
      {R"({"$defs": {"a": {"allOf": [{"$ref": "#/$defs/b"}]}, "b": {"not": {"$ref": "#/$defs/a"}}}, "$ref": "#/$defs/a"})",
       "validation would never end"},
  };
  for (const auto& [schema, message] : cases) {
    INFO(schema);
    CHECK_THAT(load_error(Json::parse(schema)), Contains(message));
  }
  // Through a member or an item the same reference is fine: each step takes a smaller value.
  CHECK(valid(Json::parse(R"({"properties": {"next": {"$ref": "#"}}})"), Json::parse(R"({"next": {"next": {}}})")));
}

TEST_CASE("annotations are accepted and assert nothing") {
  const Json schema = Json::parse(R"({"$schema": "https://json-schema.org/draft/2020-12/schema", "$id": "urn:x",
      "$comment": "c", "title": "t", "description": "d", "default": 1, "examples": [1], "format": "email",
      "deprecated": true, "readOnly": true, "writeOnly": false})");
  for (const auto& document : {Json("not an email"), Json(nullptr), Json::object(), Json::array({1})})
    CHECK(valid(schema, document));
}
