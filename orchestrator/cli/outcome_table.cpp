#include "orchestrator/cli/outcome_table.hpp"

#include <cstdio>
#include <vector>

#include "orchestrator/cli/text_table.hpp"
#include "orchestrator/study/field_units.hpp"

namespace aerobreak {
namespace {

using Json = nlohmann::ordered_json;

constexpr const char* kSpeedAxis = "impact_speed";

std::string number(const Json& value) {
  if (value.is_string()) return value.get<std::string>();
  if (value.is_number_integer()) return std::to_string(value.get<long long>());
  if (!value.is_number()) return value.dump();
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value.get<double>());
  return text;
}

// "50 [24-76]": the probability and its interval in whole per cent.
std::string percent(const Json& estimate) {
  if (estimate.at("probability").is_null()) return "-";
  const auto& interval = estimate.at("ci95");
  char text[48];
  std::snprintf(text, sizeof text, "%.0f [%.0f-%.0f]", 100.0 * estimate.at("probability").get<double>(),
                100.0 * interval[0].get<double>(), 100.0 * interval[1].get<double>());
  return text;
}

std::string fraction(const Json& value) {
  if (!value.is_number()) return "-";
  char text[16];
  std::snprintf(text, sizeof text, "%.3f", value.get<double>());
  return text;
}

std::string count(const Json& value) { return std::to_string(value.get<long long>()); }

// Results flagged outside the small-strain range, and "(+k unchecked)" for results without the
// check (migrated from a version-1 store).
std::string flagged(const Json& point) {
  std::string text = count(point.at("small_strain_exceeded"));
  const auto unchecked = point.at("small_strain_unchecked").get<long long>();
  if (unchecked > 0) text += " (+" + std::to_string(unchecked) + " unchecked)";
  return text;
}

// The axis whose values make the rows: the impact speed where the study sweeps it.
std::string row_axis(const Json& points) {
  if (points.empty() || points[0].at("grid_point").empty()) return "";
  const auto& first = points[0].at("grid_point");
  return first.contains(kSpeedAxis) ? kSpeedAxis : first.begin().key();
}

std::string with_unit(const std::string& text, const std::string& unit) {
  return unit.empty() ? text : text + " " + unit;
}

std::vector<std::string> row_of(const Json& point, const std::string& rows_by) {
  const auto& outcomes = point.at("outcomes");
  const auto axis_value = point.at("grid_point").find(rows_by);
  return {axis_value == point.at("grid_point").end() ? "" : number(*axis_value),
          count(point.at("finished")),
          percent(outcomes.at("stick")),
          percent(outcomes.at("bounce")),
          percent(outcomes.at("break-up")),
          fraction(point.at("retained_mass_fraction").at("mean")),
          count(point.at("fractured_on_wall")),
          flagged(point),
          count(outcomes.at("undetermined").at("count")),
          count(point.at("failed"))};
}

// "m/s", or in a study whose axis sets /units "m/s where /units = physical, d/tau otherwise".
std::string unit_words(const std::string& axis, const std::string& system) {
  if (system != "mixed") return study_axis_unit(axis, system);
  const std::string physical = study_axis_unit(axis, "physical"), reduced = study_axis_unit(axis, "reduced");
  if (physical == reduced) return physical;
  return (physical.empty() ? "-" : physical) + " where /units = physical, " + (reduced.empty() ? "-" : reduced) +
         " otherwise";
}

std::string legend(const std::string& rows_by, const std::string& system) {
  const std::string unit = unit_words(rows_by, system);
  const std::string axis_line = rows_by == kSpeedAxis
                                    ? "speed: the impact speed" + (unit.empty() ? "" : ", in " + unit) + ". "
                                    : (rows_by.empty() ? "" : rows_by + (unit.empty() ? "" : ": in " + unit) + ". ");
  return axis_line +
         "n: the cases with a result.\n"
         "stick, bounce, break-up: the share of the determined results (n less the undetermined) with that\n"
         "  outcome, in %, and its 95 % Wilson interval; the outcome is decided by what leaves the wall\n"
         "  (docs/IMPACT.md, section 5).\n"
         "retained: the mean mass fraction of the cluster left on the wall (1: all of it), of the determined.\n"
         "fractured on wall: the results whose deposit on the wall is in more than one piece, any outcome.\n"
         "large strain: the results in which a contact left the contact laws' small-strain range (contact\n"
         "  radius or overlap above half the primary radius, docs/MODEL.md 3.7): the laws extrapolate there.\n"
         "undet.: the results still open at the time limit (counted in n); failed: cases ended by an error.\n";
}

}  // namespace

std::string group_title(const Json& values, const std::string& system, const std::string& left_out) {
  const std::string own_system = point_unit_system(values, system);
  std::string title;
  for (const auto& [axis, value] : values.items())
    if (axis != left_out)
      title += (title.empty() ? "" : ", ") + axis + " = " + with_unit(number(value), study_axis_unit(axis, own_system));
  return title;
}

std::string speed_unit_label(const std::string& system) { return unit_words(kSpeedAxis, system); }

std::string format_outcome_table(const Json& table, const std::string& system) {
  const auto& points = table.at("grid_points");
  const std::string rows_by = row_axis(points);
  const std::string unit = study_axis_unit(rows_by, system);
  TextTable text;
  text.header = {(rows_by == kSpeedAxis ? std::string("speed") : rows_by) + (unit.empty() ? "" : "\n" + unit),
                 "n",
                 "stick %\n[95% CI]",
                 "bounce %\n[95% CI]",
                 "break-up %\n[95% CI]",
                 "retained",
                 "fractured\non wall",
                 "large\nstrain",
                 "undet.",
                 "failed"};
  for (const auto& point : points)
    text.rows_of(group_title(point.at("grid_point"), system, rows_by)).push_back(row_of(point, rows_by));
  return format_text_table(text) + "\n" + legend(rows_by, system);
}

}  // namespace aerobreak
