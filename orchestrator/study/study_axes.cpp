#include "orchestrator/study/study_axes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "orchestrator/study/canonical_json.hpp"

namespace aerobreak {
namespace {

using Json = nlohmann::ordered_json;

// The case fields that studies and correlation requests name by short names: one table. Their
// units, labels and scales come from field_units.cpp by pointer (study_axis_unit, describe_axis).
constexpr std::array<NamedCaseField, 8> kNamedFields{{
    {"impact_speed", "/impact/speed", true, false, ""},
    {"gamma_over_kn", "/material/gamma_over_kn", true, false, "gamma_over_kn"},
    {"primaries", "/cluster/generator/primaries", true, true, "N"},
    {"generator", "/cluster/generator/method", true, false, ""},
    {"fractal_dimension", "/cluster/generator/fractal_dimension", true, false, "Df"},
    {"prefactor", "/cluster/generator/prefactor", true, false, ""},
    {"geometric_standard_deviation", "/cluster/generator/geometric_standard_deviation", true, false, ""},
    {"angle", "/impact/angle", false, false, "angle"},
}};

constexpr std::size_t kMaxAxes = 8;

// The axis alias `name` (schemas/study.schema.json lists them).
const NamedCaseField* alias(const std::string& name) {
  for (const auto& field : kNamedFields)
    if (field.axis_alias && field.name == name) return &field;
  return nullptr;
}

// The named fields' `name_of` (empty: left out), joined by ", ".
template <typename NameOf>
std::string joined_field_names(NameOf name_of) {
  std::string names;
  for (const auto& field : kNamedFields)
    if (const std::string_view name = name_of(field); !name.empty())
      names += (names.empty() ? "" : ", ") + std::string(name);
  return names;
}

std::string alias_names() {
  return joined_field_names([](const NamedCaseField& field) { return field.axis_alias ? field.name : ""; });
}

bool is_integral(double x) { return std::isfinite(x) && std::floor(x) == x && std::fabs(x) < 9007199254740992.0; }

Json as_number(double x) { return is_integral(x) ? Json(static_cast<std::int64_t>(x)) : Json(x); }

// x to 15 significant digits: 0.030000000000000013 from a log range between 0.003 and 0.3 reads
// 0.03, the value a user would type. A double holds 15 digits exactly, and the change is below
// 1e-15 relative.
double fifteen_digits(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.15g", x);
  return std::strtod(text, nullptr);
}

// count values from `from` to `to`, evenly spaced in x or, for a log range, in log10 x; the end
// points are set exactly, so that a range meets the values a user types in elsewhere.
std::vector<Json> range_values(const Json& range, bool logarithmic) {
  const double from = range["from"].get<double>();
  const double to = range["to"].get<double>();
  const auto count = range["count"].get<std::size_t>();
  std::vector<Json> values;
  for (std::size_t k = 0; k < count; ++k) {
    double x;
    if (k == 0) {
      x = from;
    } else if (k + 1 == count) {
      x = to;
    } else if (logarithmic) {
      const double a = std::log10(from), b = std::log10(to);
      x = fifteen_digits(std::pow(10.0, a + (b - a) * static_cast<double>(k) / static_cast<double>(count - 1)));
    } else {
      x = fifteen_digits(from + (to - from) * static_cast<double>(k) / static_cast<double>(count - 1));
    }
    values.push_back(as_number(x));
  }
  return values;
}

StudyAxis read_axis(const std::string& name, const Json& spec, std::vector<SchemaViolation>& violations) {
  const std::string where = pointer_child("/axes", name);
  const NamedCaseField* known = alias(name);
  const bool integer = known && known->integer;
  StudyAxis axis{name, axis_pointer(name), {}};

  if (spec.contains("values")) {
    const Json& values = spec["values"];
    for (std::size_t k = 0; k < values.size(); ++k) {
      const Json& v = values[k];
      if (integer && !(v.is_number() && is_integral(v.get<double>()))) {
        violations.push_back({pointer_child(where + "/values", std::to_string(k)),
                              "must be an integer: " + name + " is a count (got " + v.dump() + ")"});
        continue;
      }
      axis.values.push_back(integer ? as_number(v.get<double>()) : v);
    }
  } else {
    const std::string kind = spec.contains("linear") ? "linear" : "log";
    const Json& range = spec[kind];
    const bool same_ends = range["from"].get<double>() == range["to"].get<double>();
    const auto count = range["count"].get<std::size_t>();
    if (count == 1 && !same_ends)
      violations.push_back({where + "/" + kind + "/count",
                            "must be at least 2 when from and to differ (count 1 is the single value from = to)"});
    else if (count > 1 && same_ends)
      violations.push_back({where + "/" + kind + "/count", "must be 1 when from = to (the values would repeat)"});
    axis.values = range_values(range, kind == "log");
    if (integer)
      for (const auto& v : axis.values)
        if (!v.is_number_integer()) {
          violations.push_back(
              {where + "/" + kind, "gives " + v.dump() + ", but " + name +
                                       " is a count: choose from, to and count so that every value is an integer"});
          break;
        }
  }

  // A repeated value would be the same case twice.
  std::map<std::string, std::size_t> seen;
  for (std::size_t k = 0; k < axis.values.size(); ++k) {
    const auto [at, inserted] = seen.emplace(canonical_dump(axis.values[k]), k);
    if (!inserted)
      violations.push_back({where, "repeats the value " + axis.values[k].dump() + " (values " +
                                       std::to_string(at->second) + " and " + std::to_string(k) + ")"});
  }
  return axis;
}

// The reference tokens of a valid JSON pointer, unescaped (RFC 6901 4).
std::vector<std::string> pointer_tokens(const std::string& pointer) {
  std::vector<std::string> tokens;
  for (std::size_t begin = 1; begin <= pointer.size();) {
    const std::size_t end = std::min(pointer.find('/', begin), pointer.size());
    std::string token = pointer.substr(begin, end - begin);
    for (std::size_t at = 0; (at = token.find('~', at)) != std::string::npos; ++at)
      token.replace(at, 2, token[at + 1] == '1' ? "/" : "~");
    tokens.push_back(std::move(token));
    begin = end + 1;
  }
  return tokens;
}

bool is_array_index(const std::string& token) {
  return token == "-" || (!token.empty() && token.find_first_not_of("0123456789") == std::string::npos);
}

}  // namespace

std::string array_growth(const nlohmann::ordered_json& base, const std::string& pointer) {
  const Json* at = &base;
  std::string walked;
  for (const auto& token : pointer_tokens(pointer)) {
    if (at && at->is_array()) {
      const bool inside = is_array_index(token) && token != "-" && token.size() <= 9 &&
                          std::stoul(token) < at->size() && (token == "0" || token.front() != '0');
      if (!inside)
        return "indexes element \"" + token + "\" of the array at " + walked + ", which has " +
               std::to_string(at->size()) + " elements: an axis may set only an element the base has";
      at = &(*at)[std::stoul(token)];
    } else if (at && at->is_object() && at->contains(token)) {
      at = &(*at)[token];
    } else {
      if (is_array_index(token))
        return "would create an array at " + (walked.empty() ? std::string("the top") : walked) + " (index " + token +
               "): an axis may set only an element the base has";
      at = nullptr;  // created as objects from here on
    }
    walked = pointer_child(walked, token);
  }
  return {};
}

std::span<const NamedCaseField> named_case_fields() { return kNamedFields; }

std::string known_covariate_names() {
  return joined_field_names([](const NamedCaseField& field) { return field.covariate; });
}

std::string axis_pointer(const std::string& name) {
  if (const NamedCaseField* a = alias(name)) return std::string(a->pointer);
  if (name.empty() || name.front() != '/') return {};
  try {
    Json::json_pointer checked(name);
  } catch (const nlohmann::json::exception&) {
    return {};
  }
  return name;
}

std::string axis_name_problem(const std::string& name) {
  if (name.size() > kMaxPointerLength)
    return "is " + std::to_string(name.size()) + " characters long; a case field is named in at most " +
           std::to_string(kMaxPointerLength);
  const std::string pointer = axis_pointer(name);
  if (pointer.empty())
    return name.empty() || name.front() != '/'
               ? "is neither an axis alias (" + alias_names() +
                     ") nor a JSON pointer into the case (starting with \"/\")"
               : "is not a valid JSON pointer (RFC 6901: \"~\" must be written \"~0\" or \"~1\")";
  const std::size_t tokens = static_cast<std::size_t>(std::count(pointer.begin(), pointer.end(), '/'));
  if (tokens > kMaxPointerTokens)
    return "has " + std::to_string(tokens) + " reference tokens; a case field is at most " +
           std::to_string(kMaxPointerTokens) + " deep";
  return {};
}

bool covers(const std::string& outer, const std::string& inner) {
  return inner == outer || inner.rfind(outer + "/", 0) == 0;
}

void check_axis_names(const nlohmann::ordered_json& axes, std::vector<SchemaViolation>& violations, bool searching) {
  const std::size_t most = searching ? kMaxAxes - 1 : kMaxAxes;
  if (axes.empty() && !searching) violations.push_back({"/axes", "must name at least 1 axis"});
  if (axes.size() > most)
    violations.push_back({"/axes", "must name at most " + std::to_string(most) + " axes" +
                                       (searching ? " beside the search axis" : "") + " (got " +
                                       std::to_string(axes.size()) + ")"});
  std::vector<std::pair<std::string, std::string>> named;  // (axis name, pointer)
  for (const auto& [name, unused] : axes.items()) {
    const std::string where = pointer_child("/axes", name);
    if (const std::string problem = axis_name_problem(name); !problem.empty()) {
      violations.push_back({where, problem});
      continue;
    }
    const std::string pointer = axis_pointer(name);
    if (pointer == "/name" || pointer == "/description" || pointer == "/$schema") {
      violations.push_back({where, "is a label, not physics: the study names each case itself"});
      continue;
    }
    for (const auto& [other, other_pointer] : named)
      if (covers(pointer, other_pointer) || covers(other_pointer, pointer))
        violations.push_back({where, "sets " +
                                         (pointer == other_pointer ? std::string("the same case field as")
                                                                   : std::string("a case field overlapping that of")) +
                                         " axis \"" + other + "\" (" + other_pointer + ")"});
    named.emplace_back(name, pointer);
  }
}

std::vector<StudyAxis> read_axes(const nlohmann::ordered_json& axes, std::vector<SchemaViolation>& violations) {
  std::vector<StudyAxis> out;
  for (const auto& [name, spec] : axes.items()) out.push_back(read_axis(name, spec, violations));
  return out;
}

}  // namespace aerobreak
