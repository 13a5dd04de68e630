#include "orchestrator/app/study_fits.hpp"

#include <algorithm>
#include <set>

#include "engine/core/version.hpp"
#include "orchestrator/fitting/correlation_json.hpp"
#include "orchestrator/fitting/correlation_set.hpp"
#include "orchestrator/study/field_units.hpp"
#include "orchestrator/study/sha256.hpp"
#include "orchestrator/study/study_axes.hpp"

namespace aerobreak {
namespace {

std::string speed_pointer() { return axis_pointer("impact_speed"); }
std::string primaries_pointer() { return axis_pointer("primaries"); }

std::vector<std::string> study_axes(const StudyRecord& study) {
  std::vector<std::string> axes;
  if (study.document.contains("axes") && study.document["axes"].is_object())
    for (const auto& [name, spec] : study.document["axes"].items()) axes.push_back(name);
  // An adaptive search's axis varies across the cases like any axis (docs/ADAPTIVE.md).
  if (study.document.contains("search")) axes.push_back(study.document["search"]["axis"].get<std::string>());
  return axes;
}

std::string axis_setting(const std::vector<std::string>& axes, const std::string& pointer) {
  for (const auto& axis : axes)
    if (axis_pointer(axis) == pointer) return axis;
  return {};
}

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

// Axes that take more than one value in the study document (a list of two or more, or a range).
bool sweeps_several(const StudyRecord& study, const std::string& axis) {
  const auto& spec = study.document["axes"][axis];
  if (spec.contains("values")) return spec["values"].size() > 1;
  for (const char* range : {"linear", "log"})
    if (spec.contains(range)) return spec[range].value("count", 1) > 1;
  return false;
}

Covariate resolve(const StudyRecord& study, const std::vector<std::string>& axes, const std::string& name) {
  for (const auto& known : named_case_fields())
    if (!known.covariate.empty() && (name == known.name || name == known.covariate)) {
      const std::string axis = axis_setting(axes, std::string(known.pointer));
      if (axis.empty())
        throw CorrelationRequestError("covariate '" + name + "' is not an axis of study " + std::to_string(study.id) +
                                          " (its axes: " + joined(axes) + ")",
                                      false);
      return {axis, field_log_scale(std::string(known.pointer))};
    }
  if (std::find(axes.begin(), axes.end(), name) == axes.end() || axis_pointer(name) == speed_pointer())
    throw CorrelationRequestError("covariate '" + name + "' is not a non-speed axis of study " +
                                      std::to_string(study.id) + " (its axes: " + joined(axes) +
                                      "; known covariates: " + known_covariate_names() + ")",
                                  false);
  return {name, false};
}

}  // namespace

CorrelationRequest correlation_request(const StudyRecord& study,
                                       const std::optional<std::vector<std::string>>& covariates) {
  const auto axes = study_axes(study);
  CorrelationRequest request;
  request.speed_axis = axis_setting(axes, speed_pointer());
  request.size_axis = axis_setting(axes, primaries_pointer());
  if (covariates) {
    std::set<std::string> seen;
    for (const auto& name : *covariates) {
      const Covariate covariate = resolve(study, axes, name);
      if (seen.insert(covariate.axis).second) request.covariates.push_back(covariate);
    }
    return request;
  }
  // By default the pooled models model the size only: every other axis splits them.
  if (!request.size_axis.empty() && sweeps_several(study, request.size_axis))
    request.covariates.push_back({request.size_axis, true});
  return request;
}

std::string request_key(const CorrelationRequest& request) {
  nlohmann::ordered_json covariates = nlohmann::ordered_json::array();
  for (const auto& covariate : request.covariates)
    covariates.push_back({covariate.axis, covariate.logarithmic ? "log" : "linear"});
  return nlohmann::ordered_json{{"speed_axis", request.speed_axis},
                                {"size_axis", request.size_axis},
                                {"covariates", covariates},
                                {"levels", request.levels}}
      .dump();
}

CaseOutcomeTable study_outcome_table(Store& store, const StudyRecord& study, std::int64_t* version,
                                     std::string* result_set_hash) {
  StudyOutcomes outcomes = store.study_outcomes(study.id);
  if (outcomes.table.cases.empty())
    throw CorrelationRequestError("study " + std::to_string(study.id) + " has no results yet: nothing to fit", true);
  if (version) *version = outcomes.result_set_version;
  if (result_set_hash) *result_set_hash = sha256_hex(outcomes.identity);
  return std::move(outcomes.table);
}

CorrelationSet study_correlations(Store& store, const StudyRecord& study, const CorrelationRequest& request) {
  Provenance provenance{study.id, {}, 0, std::string(version())};
  const CaseOutcomeTable table =
      study_outcome_table(store, study, &provenance.result_set_version, &provenance.result_set_hash);
  return compute_correlations(table, request, provenance);
}

std::shared_ptr<std::mutex> StudyFits::study_lock(std::int64_t study_id) {
  std::lock_guard lock(locks_mutex_);
  auto& entry = study_locks_[study_id];
  if (!entry) entry = std::make_shared<std::mutex>();
  return entry;
}

std::int64_t StudyFits::result_set_version(std::int64_t study_id) {
  const auto versions = store_.study_versions(study_id);
  return versions ? versions->result_set : 0;
}

std::shared_ptr<const StoredCorrelations> StudyFits::current(const StudyRecord& study,
                                                             const CorrelationRequest& request) {
  const std::string key = request_key(request);
  if (auto kept = remembered(study.id, key, result_set_version(study.id))) return kept;
  auto stored = store_.stored_correlations(study.id, key);
  if (stored && stored->result_set_version == result_set_version(study.id)) return remember(study.id, key, *stored);
  if (mode_ == Mode::read_only) return nullptr;
  const auto lock = study_lock(study.id);
  std::lock_guard guard(*lock);
  // Another request may have refitted while this one waited.
  stored = store_.stored_correlations(study.id, key);
  if (stored && stored->result_set_version == result_set_version(study.id)) return remember(study.id, key, *stored);
  return remember(study.id, key, refit(study, request, key, stored));
}

std::shared_ptr<const StoredCorrelations> StudyFits::remembered(std::int64_t study_id, const std::string& key,
                                                                std::int64_t version) const {
  std::lock_guard guard(memory_mutex_);
  const auto found = memory_.find({study_id, key});
  if (found == memory_.end() || found->second->result_set_version != version) return nullptr;
  return found->second;
}

std::shared_ptr<const StoredCorrelations> StudyFits::remember(std::int64_t study_id, const std::string& key,
                                                              StoredCorrelations set) {
  auto kept = std::make_shared<const StoredCorrelations>(std::move(set));
  std::lock_guard guard(memory_mutex_);
  if (memory_.size() >= kMaxRemembered) memory_.clear();
  memory_[{study_id, key}] = kept;
  return kept;
}

StoredCorrelations StudyFits::refit(const StudyRecord& study, const CorrelationRequest& request, const std::string& key,
                                    const std::optional<StoredCorrelations>& stored) {
  Provenance provenance{study.id, {}, 0, std::string(version())};
  const CaseOutcomeTable table =
      study_outcome_table(store_, study, &provenance.result_set_version, &provenance.result_set_hash);
  if (stored && stored->result_set_hash == provenance.result_set_hash &&
      store_.confirm_correlations(study.id, key, provenance.result_set_hash, provenance.result_set_version))
    return *store_.stored_correlations(study.id, key);
  const CorrelationSet set = compute_correlations(table, request, provenance);
  StoredCorrelations saved{0,
                           provenance.result_set_version,
                           provenance.result_set_hash,
                           provenance.aerobreak_version,
                           unix_seconds(),
                           set.seconds,
                           correlation_summary_json(set).dump()};
  std::vector<StoredFit> fits;
  for (const auto& name : fit_names(set)) {
    const auto document = *fit_json(set, name);
    fits.push_back({name, document.at("kind"), document.at("status"), document.dump()});
  }
  store_.save_correlations(study.id, key, saved, fits);
  return *store_.stored_correlations(study.id, key);
}

}  // namespace aerobreak

namespace aerobreak {

std::shared_ptr<const CorrelationSet> StudyFits::logistic_fits(const StudyRecord& study) {
  const CorrelationRequest request = correlation_request(study, std::nullopt);
  const auto stored = current(study, request);
  if (!stored)
    return std::make_shared<const CorrelationSet>(study_correlations(store_, study, request));  // read_only, stale
  {
    std::lock_guard guard(memory_mutex_);
    const auto found = read_back_.find({stored->set_id, stored->computed_at});
    if (found != read_back_.end()) return found->second;
  }
  auto set = read_back(*stored, request);
  std::lock_guard guard(memory_mutex_);
  if (read_back_.size() >= kMaxRemembered) read_back_.clear();
  read_back_[{stored->set_id, stored->computed_at}] = set;
  return set;
}

std::shared_ptr<const CorrelationSet> StudyFits::read_back(const StoredCorrelations& stored,
                                                           const CorrelationRequest& request) {
  auto set = std::make_shared<CorrelationSet>();
  set->request = request;
  const auto summary = nlohmann::ordered_json::parse(stored.summary);
  set->provenance = {summary.at("provenance").at("study"), stored.result_set_hash, stored.result_set_version,
                     stored.aerobreak_version};
  for (const auto& line : summary.at("fits"))
    if (line.at("kind") == "logistic")
      set->logistic.push_back(
          logistic_fit_from_json(nlohmann::ordered_json::parse(*store_.stored_fit(stored.set_id, line.at("name")))));
  return set;
}

}  // namespace aerobreak
