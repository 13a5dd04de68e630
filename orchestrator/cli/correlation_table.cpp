#include "orchestrator/cli/correlation_table.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <vector>

#include "orchestrator/cli/outcome_table.hpp"
#include "orchestrator/cli/text_table.hpp"
#include "orchestrator/study/field_units.hpp"

namespace aerobreak {
namespace {

using Json = nlohmann::ordered_json;
using Rows = std::vector<std::vector<std::string>>;

std::string number(const Json& value, int digits = 4) {
  if (value.is_null()) return "-";
  if (value.is_number_integer()) return std::to_string(value.get<long long>());
  if (!value.is_number()) return value.is_string() ? value.get<std::string>() : value.dump();
  char text[32];
  std::snprintf(text, sizeof text, "%.*g", digits, value.get<double>());
  return text;
}

// An end of a profile-likelihood interval: "open" where the data do not bound it (null).
std::string interval_end(const Json& value) { return value.is_null() ? "open" : number(value, 3); }

// Whether a value lies outside the range of the dose the fit saw (its validity box).
bool extrapolated(const Json& fit, const std::string& dose, const Json& value) {
  const auto validity = fit.find("validity");
  if (!value.is_number() || validity == fit.end() || !validity->contains(dose)) return false;
  const Json& box = validity->at(dose);
  const double v = value.get<double>();
  return v < box.at("min").get<double>() || v > box.at("max").get<double>();
}

// "23.4 [20.1, 27.9]", "*" after an estimate outside the doses run; "-" for a crossing without one.
std::string with_interval(const Json& fit, const std::string& dose, const Json& critical) {
  if (critical.at("estimate").is_null()) return "-";
  const auto& ci = critical.at("ci95");
  return number(critical.at("estimate"), 3) + (extrapolated(fit, dose, critical.at("estimate")) ? "*" : "") + " [" +
         interval_end(ci[0]) + ", " + interval_end(ci[1]) + "]";
}

std::string fit_state(const Json& fit) {
  const std::string status = fit.at("status");
  return status == "separation" ? "Firth" : status;
}

bool has_critical_value(const Json& fit) {
  const auto& critical = fit.at("critical");
  return std::any_of(critical.begin(), critical.end(), [](const Json& c) { return !c.at("estimate").is_null(); });
}

// A group's own fits: a pooled model (pooled_over) has its critical values in its document only.
bool shown(const Json& fit, const std::string& dose) {
  return fit.at("kind") == "logistic" && fit.at("dose") == dose && !fit.at("group").empty() &&
         fit.at("pooled_over").empty();
}

// "P(bounce) = 0 at every speed run" (from the fit's detail: "no bounce among ..." or "only ..."),
// or the status and detail of a fit that could not be made.
std::string why_no_value(const Json& fit, const std::string& dose_words) {
  const std::string response = fit.at("response").get<std::string>();
  const std::string detail = fit.value("detail", std::string());
  if (fit.at("status") == "no-transition") {
    if (detail.rfind("only ", 0) == 0) return "P(" + response + ") = 1 at every " + dose_words + " run";
    if (detail.rfind("no ", 0) == 0) return "P(" + response + ") = 0 at every " + dose_words + " run";
  }
  return "P(" + response + "): " + fit.at("status").get<std::string>() + (detail.empty() ? "" : " (" + detail + ")");
}

// "  REASON: GROUP; GROUP; ..." broken into lines of at most 100 characters after a "; ".
std::string wrapped(const std::string& reason, const std::vector<std::string>& groups) {
  std::string text, line = "  " + reason + ":";
  for (std::size_t k = 0; k < groups.size(); ++k) {
    const std::string piece = " " + groups[k] + (k + 1 < groups.size() ? ";" : "");
    if (line.size() + piece.size() > 100 && line.size() > 4) {
      text += line + "\n";
      line = "   ";
    }
    line += piece;
  }
  return text + line + "\n";
}

// The fits without any crossing, one paragraph per reason, naming their groups.
std::string folded_lines(const std::vector<const Json*>& fits, const std::string& dose_words,
                         const std::string& system) {
  std::vector<std::string> reasons;
  std::map<std::string, std::vector<std::string>> groups;
  for (const Json* fit : fits) {
    const std::string reason = why_no_value(*fit, dose_words);
    if (!groups.count(reason)) reasons.push_back(reason);
    groups[reason].push_back(group_title(fit->at("group"), system));
  }
  std::string text;
  for (const auto& reason : reasons) text += wrapped(reason, groups[reason]);
  return text;
}

}  // namespace

std::string format_critical_table(const Json& summary, const std::string& dose, const std::string& system) {
  const bool speeds = dose == "impact_speed";
  const std::string symbol = speeds ? "v" : "E";
  const std::string speed_unit = speeds ? study_axis_unit(dose, system) : "";
  const std::string unit = speed_unit.empty() ? "" : " (" + speed_unit + ")";
  TextTable table;
  table.header = {"P of",
                  "n",
                  symbol + "10" + unit + "\n[95% CI]",
                  symbol + "50" + unit + "\n[95% CI]",
                  symbol + "90" + unit + "\n[95% CI]",
                  "fit"};
  std::vector<const Json*> without_transition;
  for (const auto& fit : summary.at("fits")) {
    if (!shown(fit, dose)) continue;
    if (!has_critical_value(fit)) {
      without_transition.push_back(&fit);
      continue;
    }
    std::vector<std::string> row{fit.at("response"), number(fit.at("cases"))};
    const auto& critical = fit.at("critical");
    for (std::size_t k = 0; k < 3; ++k)
      row.push_back(k < critical.size() ? with_interval(fit, dose, critical[k]) : "-");
    row.push_back(fit_state(fit));
    table.rows_of(group_title(fit.at("group"), system)).push_back(row);
  }
  if (table.sections.empty() && without_transition.empty())
    return std::string("(no ") + (speeds ? "speed" : "energy") + " fits)\n";
  std::string text = table.sections.empty() ? "" : format_text_table(table);
  if (!without_transition.empty())
    text += std::string(text.empty() ? "" : "\n") + "No critical " + (speeds ? "speed" : "energy") +
            " in these groups:\n" + folded_lines(without_transition, speeds ? "speed" : "energy", system);
  return text;
}

std::string critical_table_legend() {
  return "P of: the outcome whose probability crosses 10, 50 and 90 % at the values of the next three columns;\n"
         "  n: the cases fitted. [95% CI]: the profile-likelihood interval; open: an end the data do not bound.\n"
         "*: outside the values run, an extrapolation of the fitted curve (docs/CORRELATIONS.md, validity box).\n"
         "fit: ok, or Firth where the outcomes separate (Firth's penalised estimate, docs/CORRELATIONS.md).\n";
}

std::string format_fit_list(const Json& summary) {
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
    text += "fragment-size fits (power law and lognormal) at " + std::to_string(fragments.size()) +
            " grid point(s): " + fragments.front().get<std::string>() +
            (fragments.size() > 1 ? " ... " + fragments.back().get<std::string>() : "") + "\n";
  return text;
}

}  // namespace aerobreak
