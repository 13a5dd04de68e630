#include "orchestrator/cli/outcome_table.hpp"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "orchestrator/cli/text_table.hpp"

namespace aerobreak {
namespace {

std::string number(const nlohmann::ordered_json& value) {
  if (value.is_string()) return value.get<std::string>();
  if (value.is_number_integer()) return std::to_string(value.get<long long>());
  if (!value.is_number()) return value.dump();
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value.get<double>());
  return text;
}

std::string probability(const nlohmann::ordered_json& estimate) {
  if (estimate.at("probability").is_null()) return "-";
  const auto& interval = estimate.at("ci95");
  char text[48];
  std::snprintf(text, sizeof text, "%.2f [%.2f, %.2f]", estimate.at("probability").get<double>(),
                interval[0].get<double>(), interval[1].get<double>());
  return text;
}

std::string fraction(const nlohmann::ordered_json& value) {
  if (!value.is_number()) return "-";
  char text[16];
  std::snprintf(text, sizeof text, "%.3f", value.get<double>());
  return text;
}

// Results flagged outside the small-strain range, and "(+k unchecked)" for results without the
// check.
std::string flagged(const nlohmann::ordered_json& point) {
  std::string text = std::to_string(point.at("small_strain_exceeded").get<long long>());
  const auto unchecked = point.at("small_strain_unchecked").get<long long>();
  if (unchecked > 0) text += " (+" + std::to_string(unchecked) + " unchecked)";
  return text;
}

}  // namespace

std::string speed_unit_label(const nlohmann::ordered_json& study_document) {
  const auto base = study_document.find("base");
  const bool physical = base != study_document.end() && base->value("units", std::string()) == "physical";
  return physical ? "m/s" : "d/tau";
}

std::string format_outcome_table(const nlohmann::ordered_json& table, const std::string& speed_unit) {
  std::vector<std::vector<std::string>> rows;
  const auto& points = table.at("grid_points");
  std::vector<std::string> header;
  if (!points.empty())
    for (const auto& [axis, value] : points[0].at("grid_point").items())
      header.push_back(axis == "impact_speed" && !speed_unit.empty() ? axis + " (" + speed_unit + ")" : axis);
  for (const char* column : {"n", "P(stick) 95% CI", "P(bounce) 95% CI", "P(break-up) 95% CI", "undetermined", "failed",
                             "retained", "fractured on wall", "large strain"})
    header.push_back(column);
  rows.push_back(header);
  for (const auto& point : points) {
    std::vector<std::string> row;
    for (const auto& [axis, value] : point.at("grid_point").items()) row.push_back(number(value));
    const auto& outcomes = point.at("outcomes");
    row.push_back(std::to_string(point.at("finished").get<long long>()));
    row.push_back(probability(outcomes.at("stick")));
    row.push_back(probability(outcomes.at("bounce")));
    row.push_back(probability(outcomes.at("break-up")));
    row.push_back(std::to_string(outcomes.at("undetermined").at("count").get<long long>()));
    row.push_back(std::to_string(point.at("failed").get<long long>()));
    row.push_back(fraction(point.at("retained_mass_fraction_mean")));
    row.push_back(std::to_string(point.at("fractured_on_wall").get<long long>()));
    row.push_back(flagged(point));
    rows.push_back(row);
  }
  return aligned_columns(rows);
}

}  // namespace aerobreak
