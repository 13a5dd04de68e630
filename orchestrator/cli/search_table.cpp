#include "orchestrator/cli/search_table.hpp"

#include <cstdio>

#include "orchestrator/study/study_expansion.hpp"

namespace aerobreak {
namespace {

std::string number(const nlohmann::ordered_json& value) {
  if (!value.is_number()) return "-";
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value.get<double>());
  return text;
}

std::string group_label(const nlohmann::ordered_json& group) {
  const std::string label = grid_label(group);
  return label.empty() ? "(one group)" : label;
}

// Nothing for a found crossing; otherwise why it is not found yet.
std::string progress_note(const nlohmann::ordered_json& estimate) {
  if (estimate.value("found", false)) return "";
  if (estimate.at("narrow_enough").get<bool>()) return " (narrow enough, not yet confirmed)";
  return " (" + estimate.at("status").get<std::string>() + ", not yet narrow enough)";
}

}  // namespace

std::string format_search_table(const nlohmann::ordered_json& groups, const std::string& axis,
                                const std::string& unit) {
  const std::string in_unit = unit.empty() ? "" : " " + unit;
  std::string text =
      "Adaptive search of " + axis + (unit.empty() ? "" : " in " + unit) + " (95 % profile-likelihood intervals):\n";
  for (const auto& g : groups) {
    text += "  " + group_label(g.at("group")) + ": " + g.at("state").get<std::string>() + " after " +
            std::to_string(g.at("rounds").get<int>()) + " rounds, " + std::to_string(g.at("cases").get<int>()) +
            " cases\n";
    for (const auto& e : g.at("estimates")) {
      char level[16];
      std::snprintf(level, sizeof level, "%.2g", e.at("level").get<double>());
      text += "    P(" + e.at("response").get<std::string>() + ") = " + level + " at " + axis + " " +
              number(e.at("estimate")) + " [" + number(e.at("lower")) + ", " + number(e.at("upper")) + "]" + in_unit +
              progress_note(e) + "\n";
    }
  }
  return text;
}

}  // namespace aerobreak
