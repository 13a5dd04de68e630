#pragma once
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "orchestrator/fitting/case_outcome.hpp"
#include "orchestrator/fitting/correlation_request.hpp"
#include "orchestrator/store/store.hpp"

namespace aerobreak {

// The table model of a study's fits (orchestrator/fitting/correlation_set.hpp, which brings Eigen:
// not included here, so that this header can follow cpp-httplib's, whose <resolv.h> defines _res).
struct CorrelationSet;

// A correlation request that does not fit the study (a covariate it does not sweep, a study without
// results): the message names the problem; `no_results` tells the two apart.
struct CorrelationRequestError : std::runtime_error {
  CorrelationRequestError(const std::string& message, bool no_results_)
      : std::runtime_error(message), no_results(no_results_) {}
  bool no_results;
};

// The request of a study's correlations: its speed and size axes and the axes the pooled models
// model (their covariates), given by name (gamma_over_kn, N or primaries, Df or fractal_dimension,
// angle, or any axis name of the study); none given: the size N when the study sweeps it over more
// than one value, so that a pooled model pools along the size only and every other axis (wall,
// gamma/k_n, generator, ...) splits it. gamma/k_n and N enter as logarithms, the others as they are.
// The lookup-table export uses the default.
CorrelationRequest correlation_request(const StudyRecord& study,
                                       const std::optional<std::vector<std::string>>& covariates);

// The canonical text of a whole request (speed and size axes, covariates, levels): the key its fits
// are stored and cached under, so that two different requests never share an answer.
std::string request_key(const CorrelationRequest& request);

// A study's outcomes, each case's N as the store keeps it (0 for a cluster file). Throws
// CorrelationRequestError for a study without results.
CaseOutcomeTable study_outcome_table(Store& store, const StudyRecord& study, std::int64_t* version = nullptr,
                                     std::string* result_set_hash = nullptr);

// A study's fits as the table model, fitted now (neither stored nor cached). Throws
// CorrelationRequestError for a study without results.
CorrelationSet study_correlations(Store& store, const StudyRecord& study, const CorrelationRequest& request);

// A study's fits, the operation that `aerobreak run`, `aerobreak export` and the REST endpoints
// share (docs/ARCHITECTURE.md, the application layer): stored and served from the store while its
// result set is unchanged: a request checks one row (the study's result-set version,
// Store::study_versions); a changed result set is read, its hash compared with the stored set's,
// and refitted only when it differs. Fitting runs outside the store's write lock, one study at a
// time; the new set is stored in one short transaction. The latest set of each study and request
// is also kept in memory, so that a request served from the cache reads one row, not the stored
// summary. The lookup-table export reads the stored fits back (logistic_fits) instead of fitting
// the study again.
class StudyFits {
 public:
  // read_only: the store is a reader (aerobreak export beside a running service): a current stored
  // set is used, anything else fitted in memory and not stored.
  enum class Mode { store, read_only };
  explicit StudyFits(Store& store, Mode mode = Mode::store) : store_(store), mode_(mode) {}
  std::shared_ptr<const StoredCorrelations> current(const StudyRecord& study, const CorrelationRequest& request);
  // The logistic fits of the default request (correlation_request(study, nullopt)) as the table
  // model, read from the stored set of the current result set (fitted and stored first if there is
  // none): what the fit table and the generated code evaluate. Kept in memory per stored set.
  std::shared_ptr<const CorrelationSet> logistic_fits(const StudyRecord& study);

 private:
  std::shared_ptr<std::mutex> study_lock(std::int64_t study_id);
  // The study's result-set version (Store::study_versions; 0 before its first result).
  std::int64_t result_set_version(std::int64_t study_id);
  StoredCorrelations refit(const StudyRecord& study, const CorrelationRequest& request, const std::string& key,
                           const std::optional<StoredCorrelations>& stored);
  // The set kept in memory for (study, request) if it was fitted to result-set version `version`.
  std::shared_ptr<const StoredCorrelations> remembered(std::int64_t study_id, const std::string& key,
                                                       std::int64_t version) const;
  std::shared_ptr<const StoredCorrelations> remember(std::int64_t study_id, const std::string& key,
                                                     StoredCorrelations set);

  // The stored set's logistic fits parsed back, or fitted now (read_only without a current set).
  std::shared_ptr<const CorrelationSet> read_back(const StoredCorrelations& stored, const CorrelationRequest& request);

  static constexpr std::size_t kMaxRemembered = 64;
  Store& store_;
  const Mode mode_;
  mutable std::mutex memory_mutex_;
  std::map<std::pair<std::int64_t, std::string>, std::shared_ptr<const StoredCorrelations>> memory_;
  // Per stored set (its id and the time it was fitted): its logistic fits read back.
  std::map<std::pair<std::int64_t, double>, std::shared_ptr<const CorrelationSet>> read_back_;
  std::mutex locks_mutex_;
  std::map<std::int64_t, std::shared_ptr<std::mutex>> study_locks_;
};

}  // namespace aerobreak
