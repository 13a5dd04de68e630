#include "orchestrator/study/study_search.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "orchestrator/study/study_axes.hpp"

namespace aerobreak {
namespace {

using Json = nlohmann::ordered_json;

double six_digits(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  return std::strtod(text, nullptr);
}

std::vector<SearchTarget> read_targets(const Json& targets) {
  std::vector<SearchTarget> out;
  for (const auto& target : targets) {
    SearchTarget t{target["response"].get<std::string>(), {}};
    for (const auto& level : target.value("levels", Json::array({0.5}))) t.levels.push_back(level.get<double>());
    out.push_back(std::move(t));
  }
  return out;
}

void check_spec(const BoundarySearchSpec& spec, const std::vector<std::string>& axis_pointers,
                std::vector<SchemaViolation>& violations) {
  if (const std::string problem = axis_name_problem(spec.axis); !problem.empty())
    violations.push_back({"/search/axis", problem});
  for (const auto& pointer : axis_pointers)
    if (!spec.pointer.empty() && (covers(pointer, spec.pointer) || covers(spec.pointer, pointer)))
      violations.push_back({"/search/axis", "sets a case field that an axis of /axes sets too (" + pointer + ")"});
  if (!(spec.from < spec.to)) violations.push_back({"/search/range", "needs from < to"});
  if (spec.logarithmic && spec.from <= 0.0)
    violations.push_back({"/search/range/from", "must be positive on the log scale"});
  if (spec.relative_width == 0.0 && spec.width == 0.0)
    violations.push_back({"/search", "needs relative_width or width: the interval width that ends a group"});
  if (spec.initial < 2) violations.push_back({"/search/initial", "must be at least 2"});
  if (spec.budget < spec.initial)
    violations.push_back({"/search/budget", "must be at least initial (" + std::to_string(spec.initial) + ")"});
  for (std::size_t t = 0; t < spec.targets.size(); ++t)
    for (std::size_t u = 0; u < t; ++u)
      if (spec.targets[t].response == spec.targets[u].response)
        violations.push_back(
            {"/search/targets/" + std::to_string(t), "repeats the response " + spec.targets[t].response});
}

}  // namespace

BoundarySearchSpec read_search_spec(const Json& search, const std::vector<std::string>& axis_pointers,
                                    std::vector<SchemaViolation>& violations) {
  BoundarySearchSpec spec;
  spec.axis = search["axis"].get<std::string>();
  if (axis_name_problem(spec.axis).empty()) spec.pointer = axis_pointer(spec.axis);
  spec.from = search["range"]["from"].get<double>();
  spec.to = search["range"]["to"].get<double>();
  spec.logarithmic = search.value("scale", std::string("log")) == "log";
  spec.targets = read_targets(search.value("targets", Json::array({{{"response", "break-up"}}})));
  spec.relative_width = search.value("relative_width", 0.0);
  spec.width = search.value("width", 0.0);
  spec.budget = search.value("budget", spec.budget);
  spec.batch = search.value("batch", spec.batch);
  spec.initial = search.value("initial", spec.initial);
  spec.resolution = search.value("resolution", spec.resolution);
  check_spec(spec, axis_pointers, violations);
  return spec;
}

double search_dose(const BoundarySearchSpec& spec, double value) { return spec.logarithmic ? std::log(value) : value; }

double search_value(const BoundarySearchSpec& spec, double dose) { return spec.logarithmic ? std::exp(dose) : dose; }

std::vector<double> search_candidates(const BoundarySearchSpec& spec) {
  const double low = search_dose(spec, spec.from), high = search_dose(spec, spec.to);
  const int count = spec.resolution;
  std::vector<double> values(static_cast<std::size_t>(count));
  for (int k = 0; k < count; ++k) {
    const double dose = low + (high - low) * static_cast<double>(k) / static_cast<double>(count - 1);
    values[static_cast<std::size_t>(k)] = k == 0           ? spec.from
                                          : k == count - 1 ? spec.to
                                                           : six_digits(search_value(spec, dose));
  }
  return values;
}

std::vector<std::size_t> initial_search_indices(const BoundarySearchSpec& spec) {
  std::vector<std::size_t> indices;
  const double last = static_cast<double>(spec.resolution - 1);
  for (int k = 0; k < spec.initial; ++k)
    indices.push_back(static_cast<std::size_t>(std::lround(last * k / static_cast<double>(spec.initial - 1))));
  return indices;
}

}  // namespace aerobreak
