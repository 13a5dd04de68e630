#include "orchestrator/study/canonical_json.hpp"

#include <cmath>
#include <cstdint>

namespace aerobreak {

nlohmann::json canonical_json(const nlohmann::ordered_json& document) {
  if (document.is_object()) {
    nlohmann::json out = nlohmann::json::object();
    for (const auto& [key, value] : document.items()) out[key] = canonical_json(value);
    return out;
  }
  if (document.is_array()) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& value : document) out.push_back(canonical_json(value));
    return out;
  }
  if (document.is_number_float()) {
    const double x = document.get<double>();
    constexpr double kExactIntegers = 9007199254740992.0;  // 2^53: every integer below is a double
    if (std::isfinite(x) && std::floor(x) == x && std::fabs(x) < kExactIntegers) return static_cast<std::int64_t>(x);
    return x;
  }
  if (document.is_number_unsigned()) return document.get<std::uint64_t>();
  if (document.is_number_integer()) return document.get<std::int64_t>();
  if (document.is_string()) return document.get<std::string>();
  if (document.is_boolean()) return document.get<bool>();
  return nullptr;
}

std::string canonical_dump(const nlohmann::ordered_json& document) { return canonical_json(document).dump(); }

}  // namespace aerobreak
