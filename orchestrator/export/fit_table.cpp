// Table (b) of docs/EXPORT.md: P(stick), P(bounce) and P(break-up) evaluated from the logistic fits of
// the correlations (docs/CORRELATIONS.md): at a size the study ran from that size's fit (logit P =
// b0 + b1 ln v, per group of the other axes), at a size it did not run from the fit pooled over its
// sizes per condition (logit P = b0 + b1 ln v + b2 ln N, fit_blocks.hpp). Each value, its pointwise
// 95 % band and where it comes from are the fitting library's predict (logistic_prediction.hpp): the
// delta method on the linear predictor, eta +- 1.96 sqrt(x' Cov x), then the logistic transform
// (Agresti, Categorical Data Analysis, 3rd ed., sec. 5.2: confidence intervals for probabilities), or
// the observed 0 or 1 of a group without a transition; a per-row flag says whether the row lies in
// the fits' validity boxes.
#include <cmath>
#include <functional>

#include "orchestrator/export/equivalent_diameters.hpp"
#include "orchestrator/export/fit_blocks.hpp"
#include "orchestrator/export/lookup_tables.hpp"

namespace aerobreak {
namespace {

constexpr int kDefaultSpeeds = 25;
constexpr const char* kOutcomeColumns[] = {"p_stick", "p_bounce", "p_break_up"};
constexpr const char* kOutcomeNames[] = {"P(stick)", "P(bounce)", "P(break-up)"};

// The speeds asked for, or 25 log-spaced over the union of the block's fits' speed ranges.
std::vector<double> speeds_for(const FitBlock& block, const ExportRequest& request) {
  if (!request.speeds.empty()) return request.speeds;
  double low = INFINITY, high = -INFINITY;
  for (const auto* fit : block.fits)
    if (fit && !fit->common.validity.empty())
      low = std::min(low, fit->common.validity[0].min), high = std::max(high, fit->common.validity[0].max);
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

// The fits of a row that give a value there (those whose boxes the row is checked against).
std::vector<const LogisticFit*> valued_fits(const FitRow& row) {
  std::vector<const LogisticFit*> fits;
  for (const auto* fit : row.block->fits)
    if (fit && block_prediction(*fit, *row.block, row.speed).source != PredictionSource::none) fits.push_back(fit);
  return fits;
}

// Inside every valued fit's validity box: every input of the fit (speed; N for a pooled fit) in its range.
bool inside(const FitRow& row) {
  for (const auto* fit : valued_fits(row))
    if (!block_prediction(*fit, *row.block, row.speed).inside) return false;
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
      for (const auto* fit : valued_fits(row)) refuse_outside(row, *fit, speed);
}

std::vector<FitRow> fit_rows(const std::vector<FitBlock>& blocks, const ExportRequest& request) {
  std::vector<FitRow> rows;
  for (const auto& block : blocks)
    for (const double speed : speeds_for(block, request)) rows.push_back({&block, speed});
  return rows;
}

using Evaluator = std::function<double(const FitRow&)>;

// The value (bound 0), the band's lower (-1) or upper (1) end, or the source (2) of outcome k's prediction.
Evaluator prediction_of(std::size_t k, int part) {
  return [k, part](const FitRow& row) {
    const LogisticFit* fit = row.block->fits[k];
    const Prediction p = fit ? block_prediction(*fit, *row.block, row.speed) : Prediction{};
    if (part == 2) return static_cast<double>(p.source);
    if (p.source == PredictionSource::none) return kMissing;
    return part == 0 ? p.band.probability : part < 0 ? p.band.lower : p.band.upper;
  };
}

nlohmann::ordered_json model_metadata() {
  return {{"column", "model: 0 = per_size, 1 = pooled_ln_n"},
          {"per_size", "a size the study ran: that size's own fit per group of the other axes, logit P = b0 + b1 ln v"},
          {"pooled_ln_n",
           "a size the study did not run: the fit over all the study's sizes per condition of the other axes, "
           "logit P = b0 + b1 ln v + b2 ln N (inside the box between the sizes run, extrapolated outside)"},
          {"band", "95 %: eta +- 1.96 sqrt(x' Cov x) on the linear predictor eta = x' b, then P = 1 / (1 + exp(-eta))"},
          {"status",
           "p_OUTCOME_status: 0 = fitted (maximum likelihood); 1 = fitted under separation (Firth); 2 = no "
           "transition in the fit's data: the observed 0 or 1, band the Wilson interval of all its cases; "
           "3 = no value (too few data, not converged, or a pooled fit under separation)"},
          {"outcomes", "each outcome is its own binomial fit: the three probabilities need not sum to 1"}};
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
  const auto axes = axis_columns(groups, {}, speed_unit_of_study != 1.0);
  for (const auto& axis : axes)
    add(axis.name, axis.unit(), axis.description(), ColumnRole::input,
        [&axis](const FitRow& row) { return axis.value(row.block->group); });
  add_axis_labels(table.metadata, axes);
  if (table.find("primaries")) {
    add("d_ve", "d", "volume-equivalent diameter d N^(1/3)", ColumnRole::derived,
        [](const FitRow& row) { return volume_equivalent_diameter(row.block->size); });
    add("d_mob", "d", "mobility-equivalent diameter (docs/EXPORT.md section 2)", ColumnRole::derived,
        [](const FitRow& row) { return mobility_equivalent_diameter(row.block->size); });
  }
  for (std::size_t k = 0; k < 3; ++k) {
    const std::string name = kOutcomeColumns[k], what = kOutcomeNames[k];
    add(name, "1", what + " from the fit", ColumnRole::output, prediction_of(k, 0));
    add(name + "_lo", "1", what + ", 95 % band, lower end", ColumnRole::output, prediction_of(k, -1));
    add(name + "_hi", "1", what + ", 95 % band, upper end", ColumnRole::output, prediction_of(k, 1));
    add(name + "_status", "1",
        "where " + what +
            " comes from: 0 fitted, 1 fitted under separation (Firth), 2 no transition "
            "in the fit's data (the observed 0 or 1), 3 no value",
        ColumnRole::output, prediction_of(k, 2));
  }
  add("inside_validity", "1",
      "1: the speed (and for model 1 the size) lies in the validity boxes of the fits that give a "
      "value; 0: extrapolated",
      ColumnRole::output, [](const FitRow& row) { return inside(row) ? 1.0 : 0.0; });
  add("model", "1",
      "the fit of the row: 0 = per_size (the size's own fit, logit P = b0 + b1 ln v), 1 = pooled_ln_n (pooled over "
      "the study's sizes, logit P = b0 + b1 ln v + b2 ln N)",
      ColumnRole::input, [](const FitRow& row) { return static_cast<double>(row.block->model); });
  return table;
}

}  // namespace aerobreak
