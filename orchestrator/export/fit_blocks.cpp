// The fits behind each block of rows of table (b) (docs/EXPORT.md, "kind=fit"): a size the study
// ran comes from the per-group logistic fits of that size (logit P = b0 + b1 ln v; the fit with the
// fewest assumptions about that size's data), a size it did not run from the fits pooled over its
// sizes per condition of the other axes (logit P = b0 + b1 ln v + b2 ln N: the correlations'
// OUTCOME.speed.pooled.cK with ln N its one covariate).
#include "orchestrator/export/fit_blocks.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "orchestrator/export/lookup_table.hpp"

namespace aerobreak {
namespace {

// The fits of stick, bounce and break-up of one group (a combination of axis values).
struct FitSet {
  nlohmann::ordered_json group;
  std::array<const LogisticFit*, 3> fits{};
};

std::size_t outcome_index(ImpactOutcome outcome) {
  return outcome == ImpactOutcome::stick ? 0 : outcome == ImpactOutcome::bounce ? 1 : 2;
}

bool speed_fit(const LogisticFit& fit) {
  return fit.dose == "impact_speed" && fit.response != ImpactOutcome::undetermined;
}

// One group's own fit (a pooled model has its covariates).
bool per_group_fit(const LogisticFit& fit) { return speed_fit(fit) && fit.covariates.empty(); }

// Whether a fit gives values (predict: fitted, or no transition in its data).
bool gives_values(const LogisticFit& fit) {
  return fit.common.status == FitStatus::no_transition ||
         (fit.common.coefficients.size() == static_cast<Eigen::Index>(2 + fit.covariates.size()) &&
          (fit.common.status == FitStatus::ok ||
           (fit.common.status == FitStatus::separation && fit.covariates.empty())));
}

template <typename Wanted>
std::vector<FitSet> fit_sets(const std::vector<LogisticFit>& fits, Wanted wanted) {
  std::vector<FitSet> sets;
  std::map<std::string, std::size_t> index;
  for (const auto& fit : fits) {
    if (!wanted(fit)) continue;
    const auto [slot, inserted] = index.emplace(fit.common.group.dump(), sets.size());
    if (inserted) sets.push_back({fit.common.group});
    sets[slot->second].fits[outcome_index(fit.response)] = &fit;
  }
  return sets;
}

bool any_values(const FitSet& set) {
  return std::any_of(set.fits.begin(), set.fits.end(),
                     [](const LogisticFit* fit) { return fit && gives_values(*fit); });
}

// A group's axes without N: the condition of the fits pooled over the sizes.
std::string other_axes(nlohmann::ordered_json group, const std::string& size_axis) {
  group.erase(size_axis);
  return group.dump();
}

FitBlock block_of(const FitSet& set, const std::string& size_axis, FitModel model) {
  return {set.group, set.group.value(size_axis, kMissing), set.fits, model};
}

// Why clusters of `size` primaries have no fit in the condition `key` of the other axes.
std::string no_pooled_fit(const CorrelationSet& set, const std::string& key, double size) {
  std::string why = "clusters of " + number_text(size) + " primaries were not run";
  const std::string size_axis = size_axis_of(set);
  if (std::none_of(set.logistic.begin(), set.logistic.end(),
                   [&](const LogisticFit& fit) { return pooled_over_size(fit, size_axis); }))
    return why +
           ", and the study does not sweep the cluster size over several values: a size it did not run needs a fit "
           "pooled over several sizes (logit P = b0 + b1 ln v + b2 ln N)";
  why +=
      "; the fit pooled over the study's sizes (logit P = b0 + b1 ln v + b2 ln N) cannot be used for the condition " +
      key + ":";
  for (const auto& fit : set.logistic)
    if (pooled_over_size(fit, size_axis) && fit.common.group.dump() == key)
      why += " " + fit.common.name + " " + std::string(to_string(fit.common.status)) +
             (fit.common.detail.empty() ? "" : " (" + fit.common.detail + ")") + ";";
  return why;
}

std::vector<double> sorted_sizes(const std::vector<double>& sizes) {
  const std::set<double> distinct(sizes.begin(), sizes.end());
  return {distinct.begin(), distinct.end()};
}

// The blocks of the asked sizes, per combination of the other axes (in grid order).
std::vector<FitBlock> asked_blocks(const CorrelationSet& set, const std::vector<FitSet>& per_size,
                                   const std::vector<double>& sizes) {
  const std::string size_axis = size_axis_of(set);
  std::set<std::pair<std::string, double>> run;  // every size that has a per-size fit, usable or not
  for (const auto& fit : set.logistic)
    if (per_group_fit(fit))
      run.insert({other_axes(fit.common.group, size_axis), key_value(fit.common.group.value(size_axis, kMissing))});
  std::map<std::string, FitSet> pooled;
  for (auto& fits :
       fit_sets(set.logistic, [&size_axis](const LogisticFit& fit) { return pooled_over_size(fit, size_axis); }))
    if (any_values(fits)) pooled.emplace(fits.group.dump(), fits);
  std::vector<std::string> combinations;
  for (const auto& fits : per_size)
    if (std::find(combinations.begin(), combinations.end(), other_axes(fits.group, size_axis)) == combinations.end())
      combinations.push_back(other_axes(fits.group, size_axis));
  std::vector<FitBlock> blocks;
  for (const auto& key : combinations)
    for (const double size : sizes) {
      const auto own = std::find_if(per_size.begin(), per_size.end(), [&](const FitSet& fits) {
        return other_axes(fits.group, size_axis) == key && fits.group.value(size_axis, kMissing) == size;
      });
      if (own != per_size.end())
        blocks.push_back(block_of(*own, size_axis, FitModel::per_size));
      else if (run.count({key, size}))
        continue;  // run, but none of its fits gives a value: no rows, as without `sizes`
      else if (const auto found = pooled.find(key); found != pooled.end()) {
        FitSet at_size = found->second;
        at_size.group = std::find_if(per_size.begin(), per_size.end(), [&](const FitSet& fits) {
                          return other_axes(fits.group, size_axis) == key;
                        })->group;  // the per-size groups' key order: the table's columns
        at_size.group[size_axis] = size;
        blocks.push_back(block_of(at_size, size_axis, FitModel::pooled_ln_n));
      } else
        throw ExportError(422, "sizes", no_pooled_fit(set, key, size));
    }
  return blocks;
}

}  // namespace

std::string size_axis_of(const CorrelationSet& set) {
  return set.request.size_axis.empty() ? "primaries" : set.request.size_axis;
}

bool pooled_over_size(const LogisticFit& fit, const std::string& size_axis) {
  return speed_fit(fit) && fit.covariates.size() == 1 && fit.covariates.front().axis == size_axis;
}

std::vector<FitBlock> fit_blocks(const CorrelationSet& set, const ExportRequest& request) {
  std::vector<FitSet> per_size;
  for (auto& fits : fit_sets(set.logistic, per_group_fit))
    if (any_values(fits)) per_size.push_back(std::move(fits));
  if (per_size.empty()) throw ExportError(409, "kind", "the study has no logistic fit of an outcome in impact speed");
  if (request.sizes.empty()) {
    std::vector<FitBlock> blocks;
    for (const auto& fits : per_size) blocks.push_back(block_of(fits, size_axis_of(set), FitModel::per_size));
    return blocks;
  }
  const auto sizes = sorted_sizes(request.sizes);
  auto blocks = asked_blocks(set, per_size, sizes);
  for (const double size : sizes)
    if (std::none_of(blocks.begin(), blocks.end(), [size](const FitBlock& block) { return block.size == size; }))
      throw ExportError(422, "sizes",
                        "no fit for clusters of " + number_text(size) + " primaries: the study ran them, but " +
                            "no outcome could be fitted (see its correlations)");
  return blocks;
}

Prediction block_prediction(const LogisticFit& fit, const FitBlock& block, double speed) {
  if (fit.covariates.empty()) return predict(fit, speed);
  return predict(fit, speed, Eigen::VectorXd::Constant(1, block.size));
}

}  // namespace aerobreak
