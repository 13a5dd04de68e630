#include "orchestrator/service/grid_filter.hpp"

#include <algorithm>

#include "orchestrator/service/http_support.hpp"

namespace aerobreak {
namespace {

constexpr std::string_view kPrefix = "axis.";

nlohmann::ordered_json axis_value(const std::string& text) {
  auto value = nlohmann::ordered_json::parse(text, nullptr, false);
  return value.is_discarded() ? nlohmann::ordered_json(text) : value;
}

}  // namespace

AxisFilter::AxisFilter(const httplib::Request& request) {
  std::size_t conditions = 0;
  for (const auto& [name, text] : request.params) {
    if (name.rfind(kPrefix, 0) != 0) continue;
    if (++conditions > kMaxConditions)
      throw RequestError{400, "at most " + std::to_string(kMaxConditions) + " axis.NAME conditions per request"};
    accepted_[name.substr(kPrefix.size())].push_back(axis_value(text));
  }
}

bool AxisFilter::accepts(const nlohmann::ordered_json& grid_point) const {
  for (const auto& [axis, values] : accepted_) {
    const auto found = grid_point.find(axis);
    if (found == grid_point.end() || std::find(values.begin(), values.end(), *found) == values.end()) return false;
  }
  return true;
}

std::vector<std::string> AxisFilter::matching_keys(
    const std::vector<std::pair<std::string, nlohmann::ordered_json>>& points) const {
  if (!points.empty())
    for (const auto& [axis, values] : accepted_)
      if (!points.front().second.contains(axis))
        throw RequestError{400, "query parameter 'axis." + axis + "': the study has no axis '" + axis + "'"};
  std::vector<std::string> keys;
  for (const auto& [key, grid_point] : points)
    if (accepts(grid_point)) keys.push_back(key);
  return keys;
}

}  // namespace aerobreak
