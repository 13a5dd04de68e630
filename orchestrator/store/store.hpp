#pragma once
#include <cstdint>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "orchestrator/store/sqlite_database.hpp"
#include "orchestrator/store/store_lock.hpp"
#include "orchestrator/store/store_types.hpp"

namespace aerobreak {

// The orchestrator's SQLite store (docs/ORCHESTRATOR.md): one file in WAL mode
// with a versioned schema (migrations.hpp). One writer: every method that changes the store runs
// on the writer connection under one mutex, each as one transaction, so that a crash at any point
// leaves either all or none of a change. Readers use connections of their own (WAL lets them read
// while the writer writes), so that the REST service never waits for the scheduler. One process
// at a time: a Store holds the store's lock (store_lock.hpp) while it lives. A reader (e.g.
// `aerobreak export` beside a running service) takes no lock and changes nothing.
class Store {
 public:
  enum class Access { orchestrator, reader };
  // The file is examined read-only first (store_file.hpp): one that is not absent, empty or an
  // aerobreak store this aerobreak can open is refused unchanged (StoreFileRefused, naming what
  // it is: another program's database, a newer aerobreak's store, not SQLite). As orchestrator:
  // throws StoreInUse when another orchestrator Store, in this process or another, has the file
  // open. As reader: opens an existing store of the current schema version read-only
  // (std::runtime_error otherwise); any writer method then fails with an SQLite error.
  // Data-file paths are kept relative to `data_directory` (data_paths.hpp; empty: the store's
  // default, STORE.data) and read back as where they lie under it now.
  explicit Store(const std::filesystem::path& file, Access access = Access::orchestrator,
                 const std::filesystem::path& data_directory = {});
  ~Store();
  Store(const Store&) = delete;
  Store& operator=(const Store&) = delete;

  const std::filesystem::path& file() const { return file_; }
  const std::filesystem::path& data_directory() const { return data_directory_; }
  int schema_version();
  // The version the file had when this Store opened it (0: created now).
  int opened_at_version() const { return opened_at_version_; }

  // --- Writer side ------------------------------------------------------------------------------

  // Stores a study and links its cases. A case is stored once, by its content hash, whatever the
  // number of studies that name it: a finished case is never rerun, a cancelled one is queued
  // again, and so is a done one named in submission.recompute (its data file was lost or damaged,
  // and its recomputation was asked for): its result stays, served, until the new one replaces it.
  // Submitting the same study (same hash) again changes nothing else and returns its id.
  SubmissionReceipt submit_study(const StudySubmission& submission);

  // The next queued case that an active study wants (submission order), marked running for the
  // job; nullopt when there is none.
  std::optional<ClaimedCase> claim_next_case(std::int64_t job_id, const std::string& worker = {});
  // The worker rank that started a case (the job's "started" message).
  void record_worker(std::int64_t case_id, int attempt, const std::string& worker);

  // Commits a result exactly once: only while the case is running the same attempt. Returns false
  // (and changes nothing) for a late, duplicate or unknown result. The data file's size and
  // checksum are kept with it, its path relative to the data folder. A result the case had (it was
  // queued again to recompute its data file) is replaced in the same transaction.
  bool commit_result(std::int64_t case_id, int attempt, const nlohmann::ordered_json& result,
                     const std::string& data_file, double wall_clock_seconds, const DataFileDigest& digest = {});
  // An attempt that ended without a result: the case goes back to the queue, or is marked failed
  // with `error` once it has failed max_attempts times. Returns the new status; nullopt when the
  // attempt was not the running one.
  std::optional<CaseStatus> record_failure(std::int64_t case_id, int attempt, AttemptEnd end, const std::string& error);
  // Cases a job was running when it ended go back to the queue. A job that crashed counts a lost
  // attempt against each of them (the crash may be the case's); a job the orchestrator stopped for
  // another reason (shut-down, another case's wall time) counts none. Returns the cases requeued.
  std::size_t requeue_job(std::int64_t job_id, const std::string& reason, bool counts_as_failure = true);
  // At start-up: cases left running by an orchestrator that died go back to the queue without a
  // failure counted (the orchestrator, not the case, stopped them).
  std::size_t requeue_interrupted();
  // An attempt stopped by a fault of the machine (its data file could not be written) goes back to
  // the queue without a failure counted. False when it was not the running attempt.
  bool requeue_attempt(std::int64_t case_id, int attempt, const std::string& reason);

  std::int64_t start_job(const std::string& command, int ranks);
  void job_started(std::int64_t job_id, std::int64_t pid, const nlohmann::ordered_json& hosts);
  void end_job(std::int64_t job_id, int exit_status, const std::string& note);
  // Jobs without an end (their orchestrator died): ended now, with a note.
  std::size_t close_orphaned_jobs();

  // Stores a study's set of fits for one request (its key: the request as canonical text),
  // replacing the one before, in one short transaction. The fitting itself happens before, outside
  // the write lock.
  void save_correlations(std::int64_t study_id, const std::string& request_key, const StoredCorrelations& set,
                         const std::vector<StoredFit>& fits);
  // A set whose result-set hash is still the study's: marks it current at `version` without
  // refitting. False when there is no such set.
  bool confirm_correlations(std::int64_t study_id, const std::string& request_key, const std::string& result_set_hash,
                            std::int64_t version);

  // Cancels an active study: its queued cases that no other active study wants become cancelled.
  // Running cases finish (their results are kept). False when there is no such active study.
  bool cancel_study(std::int64_t study_id);

  // --- Adaptive searches (docs/ADAPTIVE.md) ------------------------------------------------------

  // The searching groups of active studies whose last round has finished (none of its cases
  // queued or running), with their results: each is due its next round.
  std::vector<SearchGroupWork> search_work();
  // Stores a decision in one transaction: the round's record and cases, linked to the study, and
  // the group's state and estimates. Only when the group still stands at that round (a decision
  // made again after a restart changes nothing): returns whether it was stored.
  bool record_search_decision(const SearchDecision& decision);

  // Recomputes the per-study and per-grid-point summaries from the cases and results
  // (store_summaries.hpp). Never needed in operation (triggers keep them, migrations rebuild them);
  // for checks and repairs.
  void rebuild_summaries();

  // --- Reader side (any thread) -----------------------------------------------------------------

  std::size_t claimable_cases();
  Page<StudyRecord> studies(const PageRequest& page);
  std::optional<StudyRecord> study(std::int64_t study_id);
  // Progress and outcome table come from the summaries the store keeps as cases change
  // (store_summaries.hpp): one row per study, one per grid point, whatever the number of cases.
  std::optional<StudyProgress> progress(std::int64_t study_id);
  Page<CaseRecord> cases(std::int64_t study_id, std::optional<CaseStatus> status, const PageRequest& page);
  Page<CaseRecord> cases(std::int64_t study_id, const CaseFilter& filter, const PageRequest& page);
  Page<ResultRecord> results(std::int64_t study_id, std::optional<std::string> outcome, const PageRequest& page);
  std::vector<GridPointOutcomes> outcomes(std::int64_t study_id);
  // One row read: the versions of a study's case states and of its result set (nullopt: no such
  // study). A cache of anything computed from a study's results (an outcome table, fitted
  // correlations) keys on `result_set`; of anything that shows case states (progress, failures) on
  // `case_states` too. Both change in the transaction that changes what they stand for.
  std::optional<StudyVersions> study_versions(std::int64_t study_id);
  // Per grid point, in submission order: the outcome counts and the moments of the results'
  // scalar quantities (store_grid_queries.cpp).
  std::vector<GridPointStatistics> grid_statistics(std::int64_t study_id);
  // The study's grid points (key and axis values), in submission order.
  std::vector<std::pair<std::string, nlohmann::ordered_json>> grid_points(std::int64_t study_id);
  // Fragments of the results at the given grid points, counted per grid point and size (grid
  // points without a result are left out).
  std::vector<GridPointFragments> fragment_sizes(std::int64_t study_id, const std::vector<std::string>& grid_keys);
  // Per grid point, in submission order: the document of its first case.
  std::vector<GridPointCase> grid_point_cases(std::int64_t study_id);
  // Per grid point with a determined result, in submission order: the mass and count of the
  // fragments its determined results left, by wall contact and size (store_grid_queries.cpp).
  std::vector<GridPointFragmentMasses> fragment_masses(std::int64_t study_id);
  std::optional<CaseDetail> case_detail(std::int64_t case_id);
  // A study's search groups in order, with every round's record when `history` (empty: no search).
  std::vector<SearchGroupRecord> search_groups(std::int64_t study_id, bool history);
  std::vector<JobRecord> jobs(std::size_t limit);
  // The data files, with their recorded size and checksum, of the done cases among `hashes`.
  std::vector<StoredDataFile> data_files(const std::vector<std::string>& hashes);
  // The hashes of the cases linked to the stored study whose hash is `study_hash` (none: no such
  // study): all of a search's rounds, not only the round 0 its document expands to.
  std::vector<std::string> study_case_hashes(const std::string& study_hash);

  // Everything the statistics need about a study's results, read in one read transaction (the rows
  // and the version agree). The one place that maps store columns to CaseOutcome fields.
  StudyOutcomes study_outcomes(std::int64_t study_id);
  std::optional<StoredCorrelations> stored_correlations(std::int64_t study_id, const std::string& request_key);
  std::optional<std::string> stored_fit(std::int64_t set_id, const std::string& name);
  std::vector<std::string> stored_fit_names(std::int64_t set_id);

 private:
  class ReadConnection;
  ReadConnection read();
  void insert_study(const StudySubmission& submission, double now, SubmissionReceipt& receipt);
  // Running cases matching an SQL condition on `cases` go back to the queue, no failure counted.
  std::size_t requeue_running(const std::string& condition, const std::string& reason);

  std::filesystem::path file_;
  std::filesystem::path data_directory_;
  std::optional<StoreLock> lock_;
  void open_for_reading();
  int opened_at_version_ = 0;
  std::mutex write_mutex_;
  std::unique_ptr<SqliteDatabase> writer_;
  std::mutex pool_mutex_;
  std::vector<std::unique_ptr<SqliteDatabase>> idle_readers_;
};

// Unix time in seconds (the store's time unit).
double unix_seconds();

}  // namespace aerobreak
