#pragma once
// Which fit each block of rows of table (b) comes from (docs/EXPORT.md, "kind=fit"): a size the
// study ran from that size's own fits (per_size), a size it did not run from the fits pooled over
// its sizes (pooled_ln_n). Internal to orchestrator/export.
#include <array>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "orchestrator/export/export_request.hpp"
#include "orchestrator/fitting/logistic_prediction.hpp"

namespace aerobreak {

// The value of the `model` column.
enum class FitModel { per_size = 0, pooled_ln_n = 1 };

// One combination of the study's non-speed axes (N included) and the fits of its rows, one per
// determined outcome in the order stick, bounce, break-up; a missing fit (nullptr) gives no value.
struct FitBlock {
  nlohmann::ordered_json group;  // the axes' values, N included
  double size = 0.0;             // N (NaN when the study has no size axis)
  std::array<const LogisticFit*, 3> fits{};
  FitModel model = FitModel::per_size;
};

// The axis that counts the primaries (the request's size axis, else `primaries`).
std::string size_axis_of(const CorrelationSet& set);

// A fit of an outcome in impact speed pooled along the size alone (ln N its one covariate), one per
// condition of the other axes.
bool pooled_over_size(const LogisticFit& fit, const std::string& size_axis);

// The blocks of the request's sizes (none asked: every size the study ran), per combination of the
// other axes in grid order, sizes ascending. ExportError 409 without any per-size fit, 422 naming
// `sizes` for a size without a fit (not run and no usable fit pooled over the sizes: says why).
std::vector<FitBlock> fit_blocks(const CorrelationSet& set, const ExportRequest& request);

// What one fit of a block says at a speed (predict at the block's size).
Prediction block_prediction(const LogisticFit& fit, const FitBlock& block, double speed);

}  // namespace aerobreak
