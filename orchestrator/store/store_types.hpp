#pragma once
#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "orchestrator/fitting/case_outcome.hpp"
#include "orchestrator/fitting/mean_estimate.hpp"

namespace aerobreak {

// A case's life: queued -> running -> done | failed, back to queued when an attempt is lost or
// fails with attempts left; cancelled when no active study wants it any more.
enum class CaseStatus { queued, running, done, failed, cancelled };
std::string_view to_string(CaseStatus status);
std::optional<CaseStatus> parse_case_status(std::string_view text);

// How one attempt ended (the worker protocol's failure kinds, plus the scheduler's own).
enum class AttemptEnd { done, invalid, error, wall_time, lost, interrupted };
std::string_view to_string(AttemptEnd end);

// What the orchestrator submits: a study and its expanded cases (orchestrator/study).
struct StudySubmission {
  std::string hash;
  std::string name;
  std::string description;
  nlohmann::ordered_json document;
  int max_attempts = 3;
  double case_wall_time = 3600.0;  // seconds
  struct Case {
    std::string hash;
    nlohmann::ordered_json document;
    nlohmann::ordered_json grid_point;
    std::string grid_key;
    int replicate = 0;
    std::optional<std::int64_t> search_group{};  // an adaptive search's case: its group and round
    std::optional<int> search_round{};
  };
  std::vector<Case> cases;
  // An adaptive search's groups (docs/ADAPTIVE.md), each with its round 0 (its cases are among
  // `cases`).
  struct SearchGroup {
    std::int64_t position = 0;
    nlohmann::ordered_json group_point;
    nlohmann::ordered_json round_zero;  // the round's record: values and why
    int cases = 0;
  };
  std::vector<SearchGroup> search_groups;
  // Hashes of done cases to compute again (their data files were lost or damaged, and the
  // submitter asked for it); their results stay until the new ones replace them.
  std::vector<std::string> recompute;
};

// A search group whose last round has finished (no case of it queued or running): what the next
// round is decided from.
struct SearchGroupWork {
  std::int64_t study_id = 0;
  std::int64_t position = 0;
  nlohmann::ordered_json study_document;
  nlohmann::ordered_json group_point;
  int rounds = 0;  // rounds placed; the next is round number `rounds`
  int cases = 0;   // cases placed, failed ones included
  // The group's cases in placement order: grid point, outcome class (empty: no result) and round.
  struct Case {
    nlohmann::ordered_json grid_point;
    std::string outcome;
    int round = 0;
  };
  std::vector<Case> finished;
};

// A round's record, or a group's outcome, as the search decided it.
struct SearchDecision {
  std::int64_t study_id = 0;
  std::int64_t position = 0;
  int round = 0;                             // the round this decides (SearchGroupWork::rounds)
  std::string state;                         // the group's state after it
  nlohmann::ordered_json estimates;          // the crossings the decision rests on
  nlohmann::ordered_json plan;               // the round's record (stored when it places cases)
  std::vector<StudySubmission::Case> cases;  // the round's cases (none: the group has ended)
  std::string note;                          // why a group ended in error
};

struct SearchRoundRecord {
  int round = 0;
  double decided_at = 0.0;
  nlohmann::ordered_json plan;
};

struct SearchGroupRecord {
  std::int64_t position = 0;
  nlohmann::ordered_json group_point;
  std::string state;
  int rounds = 0;
  int cases = 0;
  nlohmann::ordered_json estimates;
  std::optional<std::string> note;
  double updated_at = 0.0;
  std::vector<SearchRoundRecord> history;  // filled on request
};

struct SubmissionReceipt {
  std::int64_t study_id = 0;
  bool existing_study = false;  // the same study was submitted before: nothing new was stored
  std::size_t cases = 0;
  std::size_t new_cases = 0;        // queued now for the first time
  std::size_t already_done = 0;     // finished for another study: not rerun
  std::size_t requeued = 0;         // cancelled before, queued again
  std::size_t recomputed = 0;       // done, but queued again: the data file was lost or damaged (asked for)
  std::size_t data_files_lost = 0;  // done cases whose data file is missing or damaged (results kept)
};

// A case's bulk data file as its worker wrote it, so that a damaged or lost file is noticed later.
struct DataFileDigest {
  std::int64_t size = -1;  // bytes; -1: not reported
  std::string sha256;      // hex; empty: not reported
};

// A case handed to a worker job.
struct ClaimedCase {
  std::int64_t case_id = 0;
  std::string hash;
  int attempt = 0;
  nlohmann::ordered_json document;
  double wall_time_limit = 0.0;  // seconds
};

struct StudyRecord {
  std::int64_t id = 0;
  std::string hash;
  std::string name;
  std::string description;
  std::string status;  // active | cancelled
  double created_at = 0.0;
  std::optional<double> cancelled_at;
  int max_attempts = 0;
  double case_wall_time = 0.0;
  std::size_t case_count = 0;
  nlohmann::ordered_json document;
};

struct StudyProgress {
  std::int64_t study_id = 0;
  std::size_t total = 0;
  std::map<std::string, std::size_t> by_status;  // every CaseStatus, zero included
  std::optional<double> first_started_at;
  std::optional<double> last_finished_at;
  double cases_per_hour = 0.0;         // finished cases over the time since the first start
  std::optional<double> seconds_left;  // remaining / rate, when there is a rate
  std::size_t search_groups = 0;       // groups of an adaptive search, all states
  std::size_t searching_groups = 0;    // of which still searching
  bool complete = false;               // nothing queued or running, no group searching
};

// Versions of what a study's read endpoints show (store_summaries.hpp); both only grow within a
// store, so that a cache keyed on them is never stale.
struct StudyVersions {
  std::int64_t case_states = 0;  // +1 whenever one of the study's cases changes status or times
  std::int64_t result_set = 0;   // +1 whenever a result of one of its cases is stored, changed or removed
};

struct CaseRecord {
  std::int64_t id = 0;
  std::string hash;
  std::string status;
  int attempts = 0;
  int failures = 0;
  int max_attempts = 0;
  double wall_time_limit = 0.0;
  std::optional<std::int64_t> job_id;
  std::optional<std::string> worker;
  double queued_at = 0.0;
  std::optional<double> started_at;
  std::optional<double> finished_at;
  std::optional<std::string> error;
  nlohmann::ordered_json grid_point;
  int replicate = 0;
  std::optional<std::string> outcome;
  // From the case's result, when it has one.
  std::optional<double> restitution;
  std::optional<double> retained_mass_fraction;
  std::optional<std::int64_t> fragment_count;
  std::optional<double> damage_ratio;
  std::optional<bool> fractured_on_wall;
  std::optional<bool> small_strain_exceeded;
};

// Which of a study's cases to list: each condition that is set must hold.
struct CaseFilter {
  std::optional<CaseStatus> status;
  std::optional<std::string> outcome;                 // stick | bounce | break-up | undetermined
  std::optional<std::vector<std::string>> grid_keys;  // only these grid points (StudySubmission::Case::grid_key)
};

struct ResultRecord {
  std::int64_t case_id = 0;
  std::string hash;
  nlohmann::ordered_json grid_point;
  int replicate = 0;
  int attempt = 0;
  std::string outcome;
  std::optional<double> restitution;
  std::optional<double> largest_fragment_share;
  std::optional<std::int64_t> fragment_count;
  std::optional<double> retained_mass_fraction;
  std::optional<double> reentrained_mass_fraction;
  std::optional<double> damage_ratio;
  std::optional<bool> fractured_on_wall;
  std::optional<bool> small_strain_exceeded;  // null: not checked (results migrated from an older store)
  std::optional<double> energy_per_contact;
  std::optional<double> energy_over_rolling;
  std::optional<std::int64_t> initial_contacts;
  std::optional<double> impact_energy;
  std::optional<double> wall_clock_seconds;
  std::optional<std::string> data_file;
  double committed_at = 0.0;
};

struct FragmentRecord {
  int rank = 0;
  std::int64_t primaries = 0;
  double mass = 0.0;
  bool on_wall = false;
  std::optional<double> normal_velocity;
  std::optional<double> radius_of_gyration;
};

struct AttemptRecord {
  int attempt = 0;
  std::optional<std::int64_t> job_id;
  std::optional<std::string> worker;
  double started_at = 0.0;
  std::optional<double> ended_at;
  std::optional<std::string> outcome;
  std::optional<std::string> error;
};

struct CaseDetail {
  CaseRecord record;
  nlohmann::ordered_json document;
  std::vector<AttemptRecord> attempts;
  std::optional<nlohmann::ordered_json> result;
  std::optional<std::string> data_file;
  DataFileDigest data_file_digest;
  std::vector<FragmentRecord> fragments;
};

// A done case's data file as recorded.
struct StoredDataFile {
  std::string hash;  // the case's
  std::string path;
  DataFileDigest digest;
};

// Outcome counts of the finished cases at one grid point of a study, and what their results say
// about the deposit, the damage and the small-strain range.
struct GridPointOutcomes {
  std::string grid_key;
  nlohmann::ordered_json grid_point;
  std::size_t cases = 0;                        // all replicates, whatever their status
  std::map<std::string, std::size_t> outcomes;  // stick, bounce, break-up, undetermined (zero included)
  std::size_t failed = 0;
  std::size_t finished() const;  // cases with a result
  // The results an outcome's share is taken of: the determined ones (those the fits and the search
  // count) for stick, bounce and break-up, every result for undetermined itself.
  std::size_t trials_for(const std::string& outcome) const;
  std::size_t fractured_on_wall = 0;       // results whose deposit is in pieces
  std::size_t small_strain_exceeded = 0;   // results flagged outside the small-strain range
  std::size_t small_strain_unchecked = 0;  // results without the check (migrated from an older store)
};

// Count, sum and sum of squared deviations from the mean (Welford's M2, statistics_functions.hpp)
// of one result quantity over the results that have it.
struct Moments {
  std::size_t count = 0;
  double sum = 0.0;
  double squared_deviations = 0.0;
};

// Its mean with standard deviation, standard error and Student interval (mean_estimate.hpp); nullopt
// when the count is 0.
std::optional<MeanEstimate> mean_estimate(const Moments& moments);

// One grid point of a study: its outcome counts and the moments of the results' scalar quantities.
struct GridPointStatistics {
  GridPointOutcomes outcomes;
  Moments retained_mass_fraction;
  Moments restitution;  // of the bounces only (count: how many)
  Moments fragment_count;
  Moments largest_fragment_share;
  Moments damage_ratio;
  Moments energy_per_contact;
};

// The fragments that the results of one grid point left: how many results, and for each fragment
// size (primaries) how many fragments of that size in all.
struct GridPointFragments {
  std::string grid_key;
  std::size_t results = 0;
  std::vector<std::pair<std::int64_t, std::size_t>> sizes;  // (primaries, fragments), by size
};

// The fragments that the determined results (stick, bounce, break-up) of one grid point left, in
// classes of (on the wall or not, size): what the lookup tables' fragment moments and sectional
// matrices are computed from (docs/EXPORT.md).
struct FragmentClass {
  bool on_wall = false;
  std::int64_t primaries = 0;
  std::size_t fragments = 0;  // fragments of this class, over all the grid point's results
  double mass = 0.0;          // their mass in all
};
struct GridPointFragmentMasses {
  std::string grid_key;
  std::size_t results = 0;  // determined results
  std::size_t break_ups = 0;
  std::vector<FragmentClass> classes;  // by on_wall, then size
};

// One grid point of a study with the document of its first case (every replicate shares the
// physics but for the seeds) and the N stored with it.
struct GridPointCase {
  std::string grid_key;
  nlohmann::ordered_json grid_point;
  nlohmann::ordered_json document;
  std::optional<std::int64_t> primaries;  // none: a cluster file
};

struct JobRecord {
  std::int64_t id = 0;
  std::string command;
  int ranks = 0;
  std::optional<std::int64_t> pid;
  double started_at = 0.0;
  std::optional<double> ended_at;
  std::optional<std::int64_t> exit_status;
  std::optional<std::string> note;
};

// A study's finished cases as the statistics read them (Store::study_outcomes), with the version
// of its result set they were read at and the identity of every result (case hash, attempt, commit
// time, and every number the statistics read of it), from which the result-set hash is computed.
struct StudyOutcomes {
  CaseOutcomeTable table;
  std::int64_t result_set_version = 0;
  std::string identity;
};

// A stored set of fits (correlation_sets): its summary document and what it was fitted to.
struct StoredCorrelations {
  std::int64_t set_id = 0;
  std::int64_t result_set_version = 0;
  std::string result_set_hash;
  std::string aerobreak_version;
  double computed_at = 0.0;
  double fit_seconds = 0.0;
  std::string summary;  // JSON text
};

struct StoredFit {
  std::string name;
  std::string kind;
  std::string status;
  std::string document;  // JSON text
};

template <typename Record>
struct Page {
  std::vector<Record> items;
  std::size_t total = 0;  // matching rows, all pages
};

struct PageRequest {
  std::size_t limit = 100;
  std::size_t offset = 0;
};

}  // namespace aerobreak
