// Table (b) of docs/EXPORT.md: P(stick) and P(break-up) evaluated from the per-group logistic fits
// of the correlations (docs/CORRELATIONS.md: logit P = b0 + b1 ln v per group of the other axes),
// with the pointwise 95 % band of LogisticFit::probability (Wald band on the logit, the delta
// method) and a per-row flag saying whether the speed lies in the fit's validity box.
#include <cmath>
#include <functional>
#include <map>
#include <set>

#include "orchestrator/export/equivalent_diameters.hpp"
#include "orchestrator/export/lookup_tables.hpp"
#include "orchestrator/fitting/correlation_set.hpp"

namespace aerobreak {
namespace {

constexpr int kDefaultSpeeds = 25;

struct GroupFits {
  nlohmann::ordered_json group;
  const LogisticFit* stick = nullptr;
  const LogisticFit* break_up = nullptr;
};

bool usable(const LogisticFit& fit) {
  return fit.dose == "impact_speed" && fit.covariates.empty() && fit.common.coefficients.size() == 2 &&
         !fit.common.validity.empty();
}

std::vector<GroupFits> group_fits(const CorrelationSet& set) {
  std::vector<GroupFits> groups;
  std::map<std::string, std::size_t> index;
  for (const auto& fit : set.logistic) {
    if (!usable(fit) || (fit.response != Outcome::stick && fit.response != Outcome::break_up)) continue;
    const auto [slot, inserted] = index.emplace(fit.common.group.dump(), groups.size());
    if (inserted) groups.push_back({fit.common.group});
    (fit.response == Outcome::stick ? groups[slot->second].stick : groups[slot->second].break_up) = &fit;
  }
  return groups;
}

// The speeds asked for, or 25 log-spaced over the union of the group's validity boxes.
std::vector<double> speeds_for(const GroupFits& fits, const ExportRequest& request) {
  if (!request.speeds.empty()) return request.speeds;
  double low = INFINITY, high = -INFINITY;
  for (const auto* fit : {fits.stick, fits.break_up})
    if (fit) low = std::min(low, fit->common.validity[0].min), high = std::max(high, fit->common.validity[0].max);
  std::vector<double> speeds;
  for (int i = 0; i < kDefaultSpeeds; ++i) speeds.push_back(low * std::pow(high / low, i / (kDefaultSpeeds - 1.0)));
  return speeds;
}

bool inside(const LogisticFit* fit, double speed) {
  if (!fit) return true;
  const auto& box = fit->common.validity[0];
  return speed >= box.min * (1.0 - 1e-12) && speed <= box.max * (1.0 + 1e-12);
}

struct FitRow {
  const GroupFits* fits;
  double speed;  // in the study's speed unit (the fits' dose)
};

using Evaluator = std::function<double(const FitRow&)>;

Evaluator band(bool stick, int bound) {
  return [stick, bound](const FitRow& row) {
    const LogisticFit* fit = stick ? row.fits->stick : row.fits->break_up;
    if (!fit) return kMissing;
    const auto point = fit->probability(row.speed);
    return bound == 0 ? point.probability : bound < 0 ? point.lower : point.upper;
  };
}

Evaluator group_value(const std::string& axis) {
  return [axis](const FitRow& row) { return row.fits->group.value(axis, kMissing); };
}

void refuse_extrapolation(const std::vector<FitRow>& rows) {
  for (const auto& row : rows)
    for (const auto* fit : {row.fits->stick, row.fits->break_up})
      if (!inside(fit, row.speed)) {
        const auto& box = fit->common.validity[0];
        throw ExportError(422, "speeds",
                          "speed " + number_text(row.speed) + " lies outside the validity box [" + number_text(box.min) + ", " +
                              number_text(box.max) + "] of fit " + fit->common.name + " (strict=true refuses extrapolation)");
      }
}

std::vector<FitRow> fit_rows(const std::vector<GroupFits>& groups, const ExportRequest& request) {
  std::set<double> sizes(request.sizes.begin(), request.sizes.end());
  std::vector<FitRow> rows;
  std::set<double> sizes_found;
  for (const auto& fits : groups) {
    const double size = fits.group.value("primaries", kMissing);
    if (!sizes.empty() && !sizes.count(size)) continue;
    sizes_found.insert(size);
    for (const double speed : speeds_for(fits, request)) rows.push_back({&fits, speed});
  }
  for (const double size : sizes)
    if (!sizes_found.count(size))
      throw ExportError(422, "sizes", "no fit for clusters of " + number_text(size) + " primaries: the fits are per grid group");
  return rows;
}

}  // namespace

LookupTable fit_table(const CorrelationSet& set, const ExportRequest& request, double speed_unit_of_study) {
  const auto groups = group_fits(set);
  if (groups.empty()) throw ExportError(409, "kind", "the study has no logistic fit of P(stick) or P(break-up) in impact speed");
  const auto rows = fit_rows(groups, request);
  if (request.strict) refuse_extrapolation(rows);
  LookupTable table;
  table.kind = "fit";
  auto add = [&](std::string name, std::string unit, std::string description, ColumnRole role, const Evaluator& value) {
    auto& column = table.add(std::move(name), std::move(unit), std::move(description), role);
    for (const auto& row : rows) column.values.push_back(value(row));
  };
  add("impact_speed", "d/tau", "normal impact speed v0", ColumnRole::speed,
      [speed_unit_of_study](const FitRow& row) { return row.speed / speed_unit_of_study; });
  for (const auto& [axis, value] : groups.front().group.items())
    if (value.is_number()) add(axis_column_name(axis), axis == "primaries" || axis == "gamma_over_kn" ? "1" : "as in the case",
                               "group axis " + axis, ColumnRole::input, group_value(axis));
  if (table.find("primaries")) {
    add("d_ve", "d", "volume-equivalent diameter d N^(1/3)", ColumnRole::derived,
        [](const FitRow& row) { return volume_equivalent_diameter(row.fits->group.value("primaries", kMissing)); });
    add("d_mob", "d", "mobility-equivalent diameter, free-molecular regime (docs/EXPORT.md)", ColumnRole::derived,
        [](const FitRow& row) { return mobility_equivalent_diameter(row.fits->group.value("primaries", kMissing)); });
  }
  add("p_stick", "1", "P(stick) from the fit", ColumnRole::output, band(true, 0));
  add("p_stick_lo", "1", "P(stick), 95 % band (delta method on the logit)", ColumnRole::output, band(true, -1));
  add("p_stick_hi", "1", "P(stick), 95 % band", ColumnRole::output, band(true, 1));
  add("p_break_up", "1", "P(break-up) from the fit", ColumnRole::output, band(false, 0));
  add("p_break_up_lo", "1", "P(break-up), 95 % band (delta method on the logit)", ColumnRole::output, band(false, -1));
  add("p_break_up_hi", "1", "P(break-up), 95 % band", ColumnRole::output, band(false, 1));
  add("inside_validity", "1", "1: the speed lies in both fits' validity boxes; 0: extrapolated", ColumnRole::output,
      [](const FitRow& row) { return inside(row.fits->stick, row.speed) && inside(row.fits->break_up, row.speed) ? 1.0 : 0.0; });
  return table;
}

}  // namespace aerobreak
