// Table (b) of docs/EXPORT.md: P(stick) and P(break-up) evaluated from the logistic fits of the
// correlations (docs/CORRELATIONS.md): at a size the study ran from that size's fit (logit P = b0 +
// b1 ln v, per group of the other axes), at a size it did not run from the fit pooled over its
// sizes (logit P = b0 + b1 ln v + b2 ln N, fit_blocks.hpp). The pointwise 95 % band is
// LogisticFit::probability's: the delta method on the linear predictor, eta +- 1.96 sqrt(x' Cov x),
// then the logistic transform (Agresti, Categorical Data Analysis, 3rd ed., sec. 5.2: confidence intervals for probabilities);
// a per-row flag says whether the row lies in the fits' validity boxes.
#include <cmath>
#include <functional>

#include "orchestrator/export/equivalent_diameters.hpp"
#include "orchestrator/export/fit_blocks.hpp"
#include "orchestrator/export/lookup_tables.hpp"

namespace aerobreak {
namespace {

constexpr int kDefaultSpeeds = 25;

// The speeds asked for, or 25 log-spaced over the union of the block's fits' speed ranges.
std::vector<double> speeds_for(const FitBlock& block, const ExportRequest& request) {
  if (!request.speeds.empty()) return request.speeds;
  double low = INFINITY, high = -INFINITY;
  for (const auto* fit : {block.stick, block.break_up})
    if (fit) low = std::min(low, fit->common.validity[0].min), high = std::max(high, fit->common.validity[0].max);
  std::vector<double> speeds;
  for (int i = 0; i < kDefaultSpeeds; ++i) speeds.push_back(low * std::pow(high / low, i / (kDefaultSpeeds - 1.0)));
  return speeds;
}

struct FitRow {
  const FitBlock* block;
  double speed;  // in the study's speed unit (the fits' dose)
};

// The value of a fit's input at a row: the speed, or the block's value of a covariate (N).
double input_at(const LogisticFit& fit, const InputRange& range, const FitRow& row) {
  return range.input == fit.dose ? row.speed : row.block->group.value(range.input, kMissing);
}

bool in_range(const InputRange& range, double value) {
  return value >= range.min * (1.0 - 1e-12) && value <= range.max * (1.0 + 1e-12);
}

// Inside the fit's validity box: every input of the fit (speed; N for a pooled fit) in its range.
bool inside(const LogisticFit* fit, const FitRow& row) {
  if (!fit) return true;
  for (const auto& range : fit->common.validity)
    if (!in_range(range, input_at(*fit, range, row))) return false;
  return true;
}

// An input of the fit at the row outside the fit's validity box refuses the request: the speed
// (`speeds`) or else the other inputs (N: `sizes`).
void refuse_outside(const FitRow& row, const LogisticFit& fit, bool speed) {
  for (const auto& range : fit.common.validity) {
    const double value = input_at(fit, range, row);
    if ((range.input == fit.dose) != speed || in_range(range, value)) continue;
    throw ExportError(422, speed ? "speeds" : "sizes",
                      (speed ? "speed " : "size N = ") + number_text(value) + " lies outside the validity box of fit " +
                          fit.common.name + ": " + range.input + " from " + number_text(range.min) + " to " +
                          number_text(range.max) + " is allowed (strict=true refuses extrapolation)");
  }
}

// strict=true: the first row outside a box refuses the request, sizes checked before speeds.
void refuse_extrapolation(const std::vector<FitRow>& rows) {
  for (const bool speed : {false, true})
    for (const auto& row : rows)
      for (const auto* fit : {row.block->stick, row.block->break_up})
        if (fit) refuse_outside(row, *fit, speed);
}

std::vector<FitRow> fit_rows(const std::vector<FitBlock>& blocks, const ExportRequest& request) {
  std::vector<FitRow> rows;
  for (const auto& block : blocks)
    for (const double speed : speeds_for(block, request)) rows.push_back({&block, speed});
  return rows;
}

using Evaluator = std::function<double(const FitRow&)>;

Evaluator band(bool stick, int bound) {
  return [stick, bound](const FitRow& row) {
    const LogisticFit* fit = stick ? row.block->stick : row.block->break_up;
    if (!fit) return kMissing;
    const auto point = fit_probability(*fit, *row.block, row.speed);
    return bound == 0 ? point.probability : bound < 0 ? point.lower : point.upper;
  };
}

nlohmann::ordered_json model_metadata() {
  return {{"column", "model: 0 = per_size, 1 = pooled_ln_n"},
          {"per_size", "a size the study ran: that size's own fit per group of the other axes, logit P = b0 + b1 ln v"},
          {"pooled_ln_n", "a size the study did not run: the fit over all the study's sizes per group of the other axes, "
                          "logit P = b0 + b1 ln v + b2 ln N (inside the box between the sizes run, extrapolated outside)"},
          {"band", "95 %: eta +- 1.96 sqrt(x' Cov x) on the linear predictor eta = x' b, then P = 1 / (1 + exp(-eta))"}};
}

}  // namespace

LookupTable fit_table(const CorrelationSet& set, const ExportRequest& request, double speed_unit_of_study) {
  const auto blocks = fit_blocks(set, request);
  const auto rows = fit_rows(blocks, request);
  if (request.strict) refuse_extrapolation(rows);
  LookupTable table;
  table.kind = "fit";
  table.metadata = {{"fit_models", model_metadata()}};
  auto add = [&](std::string name, std::string unit, std::string description, ColumnRole role, const Evaluator& value) {
    auto& column = table.add(std::move(name), std::move(unit), std::move(description), role);
    for (const auto& row : rows) column.values.push_back(value(row));
  };
  add("impact_speed", "d/tau", "normal impact speed v0", ColumnRole::speed,
      [speed_unit_of_study](const FitRow& row) { return row.speed / speed_unit_of_study; });
  std::vector<const nlohmann::ordered_json*> groups;
  for (const auto& block : blocks) groups.push_back(&block.group);
  const auto axes = axis_columns(groups, {});
  for (const auto& axis : axes)
    add(axis.name, axis.unit(), axis.description(), ColumnRole::input, [&axis](const FitRow& row) { return axis.value(row.block->group); });
  add_axis_labels(table.metadata, axes);
  if (table.find("primaries")) {
    add("d_ve", "d", "volume-equivalent diameter d N^(1/3)", ColumnRole::derived,
        [](const FitRow& row) { return volume_equivalent_diameter(row.block->size); });
    add("d_mob", "d", "mobility-equivalent diameter, free-molecular regime (docs/EXPORT.md)", ColumnRole::derived,
        [](const FitRow& row) { return mobility_equivalent_diameter(row.block->size); });
  }
  add("p_stick", "1", "P(stick) from the fit", ColumnRole::output, band(true, 0));
  add("p_stick_lo", "1", "P(stick), 95 % band (delta method on the logit)", ColumnRole::output, band(true, -1));
  add("p_stick_hi", "1", "P(stick), 95 % band", ColumnRole::output, band(true, 1));
  add("p_break_up", "1", "P(break-up) from the fit", ColumnRole::output, band(false, 0));
  add("p_break_up_lo", "1", "P(break-up), 95 % band (delta method on the logit)", ColumnRole::output, band(false, -1));
  add("p_break_up_hi", "1", "P(break-up), 95 % band", ColumnRole::output, band(false, 1));
  add("inside_validity", "1", "1: the speed (and for model 1 the size) lies in both fits' validity boxes; 0: extrapolated",
      ColumnRole::output, [](const FitRow& row) { return inside(row.block->stick, row) && inside(row.block->break_up, row) ? 1.0 : 0.0; });
  add("model", "1", "the fit of the row: 0 = per_size (the size's own fit, logit P = b0 + b1 ln v), 1 = pooled_ln_n (pooled over "
      "the study's sizes, logit P = b0 + b1 ln v + b2 ln N)", ColumnRole::input,
      [](const FitRow& row) { return static_cast<double>(row.block->model); });
  return table;
}

}  // namespace aerobreak
