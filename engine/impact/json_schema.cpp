#include "engine/impact/json_schema.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace aerobreak {
namespace {

using Json = nlohmann::ordered_json;

std::string type_name(const Json& v) {
  switch (v.type()) {
    case Json::value_t::null:
      return "null";
    case Json::value_t::boolean:
      return "boolean";
    case Json::value_t::string:
      return "string";
    case Json::value_t::array:
      return "array";
    case Json::value_t::object:
      return "object";
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
      return "integer";
    case Json::value_t::number_float:
      return "number";
    default:
      return "unknown";
  }
}

bool has_type(const Json& v, const std::string& type) {
  if (type == "null") return v.is_null();
  if (type == "boolean") return v.is_boolean();
  if (type == "string") return v.is_string();
  if (type == "array") return v.is_array();
  if (type == "object") return v.is_object();
  if (type == "number") return v.is_number();
  if (v.is_number_integer()) return true;  // "integer"
  if (!v.is_number_float()) return false;
  const double x = v.get<double>();
  return std::isfinite(x) && std::floor(x) == x;
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

// x is a whole multiple of m (> 0). Integers exactly; otherwise within 1e-9 of a whole number of m,
// since decimal fractions such as 0.0001 have no exact binary form (0.0075 / 0.0001 is not 75 in
// doubles), and every double beyond 2^53 is whole.
bool is_multiple(const Json& x, const Json& m) {
  if (x.is_number_integer() && m.is_number_integer()) {
    const auto divisor = m.get<std::int64_t>();
    return x.is_number_unsigned() ? x.get<std::uint64_t>() % static_cast<std::uint64_t>(divisor) == 0
                                  : x.get<std::int64_t>() % divisor == 0;
  }
  const double quotient = x.get<double>() / m.get<double>();
  if (!std::isfinite(quotient)) return false;
  if (std::abs(quotient) >= 9007199254740992.0) return true;
  return std::abs(quotient - std::round(quotient)) <= 1e-9;
}

bool numbers_equal(const Json& a, const Json& b) {
  if (a.is_number_integer() && b.is_number_integer()) {
    if (a.is_number_unsigned() != b.is_number_unsigned()) {
      const Json& signed_one = a.is_number_unsigned() ? b : a;
      const Json& unsigned_one = a.is_number_unsigned() ? a : b;
      return signed_one.get<std::int64_t>() >= 0 &&
             static_cast<std::uint64_t>(signed_one.get<std::int64_t>()) == unsigned_one.get<std::uint64_t>();
    }
    return a.is_number_unsigned() ? a.get<std::uint64_t>() == b.get<std::uint64_t>()
                                  : a.get<std::int64_t>() == b.get<std::int64_t>();
  }
  return a.get<double>() == b.get<double>();
}

// One validation pass: the schema's references, whether defaults are inserted, and the violations
// found so far.
class Validator {
 public:
  Validator(const JsonSchema::Compiled& compiled, bool complete, std::vector<SchemaViolation>& out)
      : compiled_(compiled), complete_(complete), out_(out) {}

  void check(const Json& schema, Json& value, const std::string& pointer) const {
    if (schema.is_boolean()) {
      if (!schema.get<bool>()) out_.push_back({pointer, "is not allowed here"});
      return;
    }
    if (const auto reference = schema.find("$ref"); reference != schema.end())
      check(*compiled_.references.at(reference->get<std::string>()), value, pointer);
    if (!check_type(schema, value, pointer)) return;  // the other keywords would only repeat the type error
    check_enum_and_const(schema, value, pointer);
    if (value.is_number()) check_number(schema, value, pointer);
    if (value.is_string()) check_string(schema, value.get<std::string>(), pointer);
    if (value.is_array()) check_array(schema, value, pointer);
    if (value.is_object()) check_object(schema, value, pointer);
    check_all_and_any(schema, value, pointer);
    check_one_of(schema, value, pointer);
    check_not_and_conditional(schema, value, pointer);
  }

 private:
  void fail(const std::string& pointer, const std::string& message) const { out_.push_back({pointer, message}); }

  // Whether `value` satisfies `schema`, without defaults and without reporting.
  bool matches(const Json& schema, const Json& value) const { return first_violation(schema, value, "").empty(); }

  std::string first_violation(const Json& schema, const Json& value, const std::string& pointer) const {
    Json copy = value;
    std::vector<SchemaViolation> inner;
    Validator(compiled_, false, inner).check(schema, copy, pointer);
    return inner.empty() ? std::string() : describe({inner.front()});
  }

  bool check_type(const Json& schema, const Json& value, const std::string& pointer) const {
    const auto type = schema.find("type");
    if (type == schema.end()) return true;
    bool ok = false;
    std::string wanted;
    for (const auto& name : type->is_string() ? Json::array({*type}) : *type) {
      ok = ok || has_type(value, name.get<std::string>());
      wanted += (wanted.empty() ? "" : " or ") + name.get<std::string>();
    }
    if (ok) return true;
    const bool vowel = std::string("aeiou").find(wanted[0]) != std::string::npos;
    fail(pointer, std::string("must be ") + (vowel ? "an " : "a ") + wanted + " (got " + type_name(value) + " " +
                      shown(value) + ")");
    return false;
  }

  void check_enum_and_const(const Json& schema, const Json& value, const std::string& pointer) const {
    if (const auto options = schema.find("enum"); options != schema.end()) {
      bool found = false;
      std::string allowed;
      for (const auto& option : *options) {
        found = found || json_equal(option, value);
        allowed += (allowed.empty() ? "" : ", ") + option.dump();
      }
      if (!found) fail(pointer, "must be one of " + allowed + " (got " + shown(value) + ")");
    }
    if (const auto constant = schema.find("const"); constant != schema.end() && !json_equal(*constant, value))
      fail(pointer, "must be " + constant->dump() + " (got " + shown(value) + ")");
  }

  void check_number(const Json& schema, const Json& value, const std::string& pointer) const {
    const double x = value.get<double>();
    if (!std::isfinite(x)) fail(pointer, "must be a finite number");
    const auto bound = [&](const char* keyword, const char* relation, auto holds) {
      const auto limit = schema.find(keyword);
      if (limit != schema.end() && !holds(x, limit->template get<double>()))
        fail(pointer, std::string("must be ") + relation + " " + number_text(limit->template get<double>()) + " (got " +
                          number_text(x) + ")");
    };
    bound("minimum", ">=", [](double a, double b) { return a >= b; });
    bound("maximum", "<=", [](double a, double b) { return a <= b; });
    bound("exclusiveMinimum", ">", [](double a, double b) { return a > b; });
    bound("exclusiveMaximum", "<", [](double a, double b) { return a < b; });
    if (const auto divisor = schema.find("multipleOf"); divisor != schema.end() && !is_multiple(value, *divisor))
      fail(pointer, "must be a multiple of " + divisor->dump() + " (got " + number_text(x) + ")");
  }

  void check_string(const Json& schema, const std::string& text, const std::string& pointer) const {
    const std::size_t length = code_points(text);
    if (const auto least = schema.find("minLength"); least != schema.end() && length < least->get<double>())
      fail(pointer, "must have at least " + least->dump() + " characters (got " + std::to_string(length) + ")");
    if (const auto most = schema.find("maxLength"); most != schema.end() && length > most->get<double>())
      fail(pointer, "must have at most " + most->dump() + " characters (got " + std::to_string(length) + ")");
  }

  void check_array(const Json& schema, Json& value, const std::string& pointer) const {
    const auto size = std::to_string(value.size());
    if (const auto least = schema.find("minItems"); least != schema.end() && value.size() < least->get<double>())
      fail(pointer, "must have at least " + least->dump() + " items (got " + size + ")");
    if (const auto most = schema.find("maxItems"); most != schema.end() && value.size() > most->get<double>())
      fail(pointer, "must have at most " + most->dump() + " items (got " + size + ")");
    if (const auto items = schema.find("items"); items != schema.end())
      for (std::size_t k = 0; k < value.size(); ++k) check(*items, value[k], pointer_child(pointer, std::to_string(k)));
  }

  void check_object(const Json& schema, Json& value, const std::string& pointer) const {
    if (const auto required = schema.find("required"); required != schema.end())
      for (const auto& name : *required)
        if (!value.contains(name.get<std::string>()))
          fail(pointer_child(pointer, name.get<std::string>()), "is required");
    static const Json no_properties = Json::object();
    const auto found = schema.find("properties");
    const Json& known = found == schema.end() ? no_properties : *found;
    for (const auto& [name, sub] : known.items()) {
      if (complete_ && !value.contains(name) && sub.is_object() && sub.contains("default"))
        value[name] = sub["default"];
      if (value.contains(name)) check(sub, value[name], pointer_child(pointer, name));
    }
    const auto extra = schema.find("additionalProperties");
    if (extra == schema.end()) return;
    for (auto& [name, sub_value] : value.items()) {
      if (known.contains(name)) continue;
      if (extra->is_boolean() && !extra->get<bool>()) {
        std::string allowed;
        for (const auto& [k, unused] : known.items()) allowed += (allowed.empty() ? "" : ", ") + k;
        fail(pointer_child(pointer, name),
             "is not a recognised field" + (allowed.empty() ? std::string() : " (allowed here: " + allowed + ")"));
      } else {
        check(*extra, sub_value, pointer_child(pointer, name));
      }
    }
  }

  // "1: why; 2: why" for each alternative of anyOf or oneOf.
  std::string why_none(const Json& options, const Json& value, const std::string& pointer) const {
    std::string why;
    for (std::size_t k = 0; k < options.size(); ++k)
      why += (k ? "; " : "") + std::to_string(k + 1) + ": " + first_violation(options[k], value, pointer);
    return why;
  }

  void check_all_and_any(const Json& schema, Json& value, const std::string& pointer) const {
    if (const auto all = schema.find("allOf"); all != schema.end())
      for (const auto& sub : *all) check(sub, value, pointer);
    const auto any = schema.find("anyOf");
    if (any == schema.end()) return;
    for (const auto& sub : *any) {
      if (!matches(sub, value)) continue;
      if (complete_) check(sub, value, pointer);
      return;
    }
    fail(pointer, "must match at least one of " + std::to_string(any->size()) + " alternatives, matches none (" +
                      why_none(*any, value, pointer) + ")");
  }

  void check_one_of(const Json& schema, Json& value, const std::string& pointer) const {
    const auto one = schema.find("oneOf");
    if (one == schema.end()) return;
    std::vector<std::size_t> matching;
    for (std::size_t k = 0; k < one->size(); ++k)
      if (matches((*one)[k], value)) matching.push_back(k);
    const std::string count = std::to_string(one->size());
    if (matching.size() == 1) {
      if (complete_) check((*one)[matching.front()], value, pointer);
    } else if (matching.empty()) {
      fail(pointer, "must match exactly one of " + count + " alternatives, matches none (" +
                        why_none(*one, value, pointer) + ")");
    } else {
      std::string which;
      for (std::size_t k : matching) which += (which.empty() ? "" : " and ") + std::to_string(k + 1);
      fail(pointer, "must match exactly one of " + count + " alternatives, matches " + which);
    }
  }

  void check_not_and_conditional(const Json& schema, Json& value, const std::string& pointer) const {
    if (const auto forbidden = schema.find("not"); forbidden != schema.end() && matches(*forbidden, value))
      fail(pointer, "matches a form that is not allowed here");
    const auto condition = schema.find("if");
    if (condition == schema.end()) return;
    const auto branch = schema.find(matches(*condition, value) ? "then" : "else");
    if (branch != schema.end()) check(*branch, value, pointer);
  }

  const JsonSchema::Compiled& compiled_;
  bool complete_;
  std::vector<SchemaViolation>& out_;
};

}  // namespace

std::string describe(const std::vector<SchemaViolation>& violations) {
  std::string text;
  for (const auto& v : violations) {
    if (!text.empty()) text += "\n";
    text += (v.pointer.empty() ? std::string("(document)") : v.pointer) + ": " + v.message;
  }
  return text;
}

JsonSchema::JsonSchema(nlohmann::ordered_json schema) : compiled_(compile_json_schema(std::move(schema))) {}

std::vector<SchemaViolation> JsonSchema::validate(const nlohmann::ordered_json& document) const {
  Json copy = document;
  std::vector<SchemaViolation> out;
  Validator(*compiled_, false, out).check(compiled_->schema, copy, "");
  return out;
}

std::vector<SchemaViolation> JsonSchema::validate_and_complete(nlohmann::ordered_json& document) const {
  std::vector<SchemaViolation> out;
  Validator(*compiled_, true, out).check(compiled_->schema, document, "");
  return out;
}

std::optional<nlohmann::ordered_json> without_violating_members(const JsonSchema& schema,
                                                                nlohmann::ordered_json document,
                                                                const std::vector<SchemaViolation>& violations) {
  for (const auto& violation : violations) {
    if (violation.pointer.empty()) return std::nullopt;
    const Json::json_pointer member(violation.pointer);
    if (!document.contains(member)) continue;
    Json& parent = document[member.parent_pointer()];
    if (!parent.is_object()) return std::nullopt;
    parent.erase(member.back());
  }
  if (!schema.validate_and_complete(document).empty()) return std::nullopt;
  return document;
}

bool json_equal(const nlohmann::ordered_json& a, const nlohmann::ordered_json& b) {
  if (a.is_number() && b.is_number()) return numbers_equal(a, b);
  if (a.type() != b.type()) return false;
  if (a.is_array()) {
    if (a.size() != b.size()) return false;
    for (std::size_t k = 0; k < a.size(); ++k)
      if (!json_equal(a[k], b[k])) return false;
    return true;
  }
  if (a.is_object()) {
    if (a.size() != b.size()) return false;
    for (const auto& [key, value] : a.items()) {
      const auto other = b.find(key);
      if (other == b.end() || !json_equal(value, *other)) return false;
    }
    return true;
  }
  return a == b;
}

std::size_t code_points(const std::string& utf8) {
  std::size_t count = 0;
  for (const char c : utf8)
    if ((static_cast<unsigned char>(c) & 0xc0) != 0x80) ++count;  // not a continuation byte (10xxxxxx)
  return count;
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
