#include "orchestrator/cli/correlation_table.hpp"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "orchestrator/cli/text_table.hpp"

namespace aerobreak {
namespace {

using Rows = std::vector<std::vector<std::string>>;

std::string number(const nlohmann::ordered_json& value) {
  if (value.is_null()) return "-";
  if (value.is_number_integer()) return std::to_string(value.get<long long>());
  if (!value.is_number()) return value.is_string() ? value.get<std::string>() : value.dump();
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value.get<double>());
  return text;
}

std::string with_interval(const nlohmann::ordered_json& critical) {
  const auto& ci = critical.at("ci95");
  return number(critical.at("estimate")) + " [" + number(ci[0]) + ", " + number(ci[1]) + "]";
}

std::string fit_state(const nlohmann::ordered_json& fit) {
  const std::string status = fit.at("status");
  if (status == "ok") return "ok";
  if (status == "separation") return "separation: Firth";
  return status;
}

}  // namespace

std::string format_critical_table(const nlohmann::ordered_json& summary, const std::string& dose) {
  const std::string symbol = dose == "impact_speed" ? "v" : "E";
  Rows rows;
  std::vector<std::string> axes;
  for (const auto& fit : summary.at("fits")) {
    // A group's own fits: a pooled model (pooled_over) has its critical values in its document only.
    if (fit.at("kind") != "logistic" || fit.at("dose") != dose || fit.at("group").empty() || !fit.at("pooled_over").empty())
      continue;
    if (rows.empty()) {
      for (const auto& [axis, value] : fit.at("group").items()) axes.push_back(axis);
      std::vector<std::string> header = axes;
      for (const std::string column : {"P of", "n", "10 [95% CI]", "50 [95% CI]", "90 [95% CI]", "fit"})
        header.push_back(column[0] == '1' || column[0] == '5' || column[0] == '9' ? symbol + column : column);
      rows.push_back(header);
    }
    std::vector<std::string> row;
    for (const auto& axis : axes) row.push_back(number(fit.at("group").value(axis, nlohmann::ordered_json())));
    row.push_back(fit.at("response"));
    row.push_back(number(fit.at("cases")));
    const auto& critical = fit.at("critical");
    for (std::size_t k = 0; k < 3; ++k) row.push_back(k < critical.size() ? with_interval(critical[k]) : "-");
    row.push_back(fit_state(fit));
    rows.push_back(row);
  }
  if (rows.empty()) return std::string("(no ") + (dose == "impact_speed" ? "speed" : "energy") + " fits)\n";
  return aligned_columns(rows);
}

std::string format_fit_list(const nlohmann::ordered_json& summary) {
  Rows rows{{"fit", "status", "n", "detail"}};
  for (const auto& fit : summary.at("fits")) {
    std::string detail = fit.value("detail", std::string());
    if (fit.contains("exponents"))
      for (const auto& [axis, exponent] : fit.at("exponents").items())
        detail += (detail.empty() ? "" : "; ") + axis + " exponent " + number(exponent.at("estimate")) + " [" +
                  number(exponent.at("ci95")[0]) + ", " + number(exponent.at("ci95")[1]) + "]";
    rows.push_back({fit.at("name"), fit.at("status"), number(fit.at("cases")), detail});
  }
  std::string text = aligned_columns(rows);
  const auto& fragments = summary.at("fragment_sizes");
  if (!fragments.empty())
    text += "fragment-size fits (power law and lognormal) at " + std::to_string(fragments.size()) + " grid point(s): " +
            fragments.front().get<std::string>() + (fragments.size() > 1 ? " ... " + fragments.back().get<std::string>() : "") + "\n";
  return text;
}

}  // namespace aerobreak
