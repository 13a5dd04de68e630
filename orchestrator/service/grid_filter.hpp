#pragma once
#include <httplib.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace aerobreak {

// Conditions on a study's axes from query parameters `axis.NAME=VALUE`: VALUE is JSON (0.01,
// "jkr", true) or, when it does not parse, a string; a name given several times accepts any of its
// values. Grid points are matched by JSON equality of their axis values (numbers as numbers, so
// 0.010 and 1e-2 match 0.01).
class AxisFilter {
 public:
  // RequestError 400 when there are more than kMaxConditions of them.
  explicit AxisFilter(const httplib::Request& request);
  bool empty() const { return accepted_.empty(); }
  // The keys of the grid points (key, axis values) that meet every condition; RequestError 400
  // naming an axis that the study does not have.
  std::vector<std::string> matching_keys(
      const std::vector<std::pair<std::string, nlohmann::ordered_json>>& points) const;

  static constexpr std::size_t kMaxConditions = 64;

 private:
  bool accepts(const nlohmann::ordered_json& grid_point) const;
  std::map<std::string, std::vector<nlohmann::ordered_json>> accepted_;
};

}  // namespace aerobreak
