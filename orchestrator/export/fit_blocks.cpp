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

// The fits of stick and break-up of one group (a combination of axis values).
struct FitPair {
  nlohmann::ordered_json group;
  const LogisticFit* stick = nullptr;
  const LogisticFit* break_up = nullptr;
};

bool speed_fit(const LogisticFit& fit) {
  return fit.dose == "impact_speed" && (fit.response == Outcome::stick || fit.response == Outcome::break_up);
}

// One group's own fit (a pooled model has its covariates).
bool per_group_fit(const LogisticFit& fit) { return speed_fit(fit) && fit.covariates.empty(); }

bool usable_per_size(const LogisticFit& fit) {
  return per_group_fit(fit) && fit.common.coefficients.size() == 2 && !fit.common.validity.empty();
}

std::string size_axis_of(const CorrelationSet& set) { return set.request.size_axis.empty() ? "primaries" : set.request.size_axis; }

// A fit pooled along the size alone (ln N its one covariate), one per condition of the other axes.
bool pooled_over_size(const LogisticFit& fit, const std::string& size_axis) {
  return speed_fit(fit) && fit.covariates.size() == 1 && fit.covariates.front().axis == size_axis;
}

// Firth's estimate under separation is finite, but its Wald band is unreliable (Heinze & Schemper,
// Statist. Med. 21 (2002) 2409): a pooled fit is used to extrapolate across sizes only when ML converged.
bool usable_pooled(const LogisticFit& fit, const std::string& size_axis) {
  return pooled_over_size(fit, size_axis) && fit.common.status == FitStatus::ok && fit.common.coefficients.size() == 3 &&
         fit.common.validity.size() == 2;
}

template <typename Usable>
std::vector<FitPair> fit_pairs(const std::vector<LogisticFit>& fits, Usable usable) {
  std::vector<FitPair> pairs;
  std::map<std::string, std::size_t> index;
  for (const auto& fit : fits) {
    if (!usable(fit)) continue;
    const auto [slot, inserted] = index.emplace(fit.common.group.dump(), pairs.size());
    if (inserted) pairs.push_back({fit.common.group});
    (fit.response == Outcome::stick ? pairs[slot->second].stick : pairs[slot->second].break_up) = &fit;
  }
  return pairs;
}

// A group's axes without N: the group of the fits pooled over the sizes.
std::string other_axes(nlohmann::ordered_json group, const std::string& size_axis) {
  group.erase(size_axis);
  return group.dump();
}

FitBlock block_of(const FitPair& pair, const std::string& size_axis, FitModel model) {
  return {pair.group, pair.group.value(size_axis, kMissing), pair.stick, pair.break_up, model};
}

// Why clusters of `size` primaries have no fit in the group `key` of the other axes.
std::string no_pooled_fit(const CorrelationSet& set, const std::string& key, double size) {
  std::string why = "clusters of " + number_text(size) + " primaries were not run";
  const std::string size_axis = size_axis_of(set);
  if (std::none_of(set.logistic.begin(), set.logistic.end(), [&](const LogisticFit& fit) { return pooled_over_size(fit, size_axis); }))
    return why + ", and the study does not sweep the cluster size over several values: a size it did not run needs a fit pooled "
                 "over several sizes (logit P = b0 + b1 ln v + b2 ln N)";
  why += "; the fit pooled over the study's sizes (logit P = b0 + b1 ln v + b2 ln N) cannot be used for the condition " + key + ":";
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
std::vector<FitBlock> asked_blocks(const CorrelationSet& set, const std::vector<FitPair>& per_size,
                                   const std::vector<double>& sizes) {
  const std::string size_axis = size_axis_of(set);
  std::set<std::pair<std::string, double>> run;  // every size that has a per-size fit, usable or not
  for (const auto& fit : set.logistic)
    if (per_group_fit(fit))
      run.insert({other_axes(fit.common.group, size_axis), key_value(fit.common.group.value(size_axis, kMissing))});
  std::map<std::string, FitPair> pooled;
  const auto usable = [&size_axis](const LogisticFit& fit) { return usable_pooled(fit, size_axis); };
  for (auto& pair : fit_pairs(set.logistic, usable)) pooled.emplace(pair.group.dump(), pair);
  std::vector<std::string> combinations;
  for (const auto& pair : per_size)
    if (std::find(combinations.begin(), combinations.end(), other_axes(pair.group, size_axis)) == combinations.end())
      combinations.push_back(other_axes(pair.group, size_axis));
  std::vector<FitBlock> blocks;
  for (const auto& key : combinations)
    for (const double size : sizes) {
      const auto own = std::find_if(per_size.begin(), per_size.end(), [&](const FitPair& pair) {
        return other_axes(pair.group, size_axis) == key && pair.group.value(size_axis, kMissing) == size;
      });
      if (own != per_size.end()) blocks.push_back(block_of(*own, size_axis, FitModel::per_size));
      else if (run.count({key, size})) continue;  // run, but neither of its fits could be made: no rows, as without `sizes`
      else if (const auto found = pooled.find(key); found != pooled.end()) {
        FitPair at_size = found->second;
        at_size.group = std::find_if(per_size.begin(), per_size.end(), [&](const FitPair& pair) {
                          return other_axes(pair.group, size_axis) == key;
                        })->group;  // the per-size groups' key order: the table's columns
        at_size.group[size_axis] = size;
        blocks.push_back(block_of(at_size, size_axis, FitModel::pooled_ln_n));
      } else
        throw ExportError(422, "sizes", no_pooled_fit(set, key, size));
    }
  return blocks;
}

}  // namespace

std::vector<FitBlock> fit_blocks(const CorrelationSet& set, const ExportRequest& request) {
  const auto per_size = fit_pairs(set.logistic, usable_per_size);
  if (per_size.empty()) throw ExportError(409, "kind", "the study has no logistic fit of P(stick) or P(break-up) in impact speed");
  if (request.sizes.empty()) {
    std::vector<FitBlock> blocks;
    for (const auto& pair : per_size) blocks.push_back(block_of(pair, size_axis_of(set), FitModel::per_size));
    return blocks;
  }
  const auto sizes = sorted_sizes(request.sizes);
  auto blocks = asked_blocks(set, per_size, sizes);
  for (const double size : sizes)
    if (std::none_of(blocks.begin(), blocks.end(), [size](const FitBlock& block) { return block.size == size; }))
      throw ExportError(422, "sizes", "no fit for clusters of " + number_text(size) + " primaries: the study ran them, but " +
                                          "neither P(stick) nor P(break-up) could be fitted (see its correlations)");
  return blocks;
}

BandPoint fit_probability(const LogisticFit& fit, const FitBlock& block, double speed) {
  if (fit.covariates.empty()) return fit.probability(speed);
  return fit.probability(speed, Eigen::VectorXd::Constant(1, block.size));
}

}  // namespace aerobreak
