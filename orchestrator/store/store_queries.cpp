// The store's reader side: every query runs on a pooled read-only connection.
#include <algorithm>
#include <array>
#include <map>

#include "orchestrator/store/data_paths.hpp"
#include "orchestrator/store/store.hpp"
#include "orchestrator/store/store_read_connection.hpp"

namespace aerobreak {
namespace {

std::size_t count(SqliteStatement&& statement) {
  statement.step();
  return static_cast<std::size_t>(statement.integer(0));
}

StudyRecord study_from(const SqliteStatement& row) {
  StudyRecord study;
  study.id = row.integer(0);
  study.hash = row.text(1);
  study.name = row.text(2);
  study.description = row.text(3);
  study.status = row.text(4);
  study.created_at = row.real(5);
  study.cancelled_at = row.optional_real(6);
  study.max_attempts = static_cast<int>(row.integer(7));
  study.case_wall_time = row.real(8);
  study.case_count = static_cast<std::size_t>(row.integer(9));
  study.document = nlohmann::ordered_json::parse(row.text(10));
  return study;
}

constexpr std::string_view kStudyColumns =
    "SELECT s.id, s.hash, s.name, s.description, s.status, s.created_at, s.cancelled_at, s.max_attempts, "
    "s.case_wall_time, (SELECT u.queued + u.running + u.done + u.failed + u.cancelled FROM study_summaries u "
    "WHERE u.study_id = s.id), s.document FROM studies s ";

constexpr std::string_view kCaseColumns =
    "SELECT c.id, c.hash, c.status, c.attempts, c.failures, c.max_attempts, c.wall_time_limit, c.job_id, c.worker, "
    "c.queued_at, c.started_at, c.finished_at, c.error, sc.grid_point, sc.replicate, r.outcome, r.restitution, "
    "r.retained_mass_fraction, r.fragment_count, r.damage_ratio, r.fractured_on_wall, r.small_strain_exceeded "
    "FROM study_cases sc JOIN cases c ON c.id = sc.case_id LEFT JOIN results r ON r.case_id = c.id ";

std::optional<bool> optional_flag(const SqliteStatement& row, int column) {
  const auto value = row.optional_integer(column);
  return value ? std::optional(*value != 0) : std::nullopt;
}

CaseRecord case_from(const SqliteStatement& row) {
  CaseRecord record;
  record.id = row.integer(0);
  record.hash = row.text(1);
  record.status = row.text(2);
  record.attempts = static_cast<int>(row.integer(3));
  record.failures = static_cast<int>(row.integer(4));
  record.max_attempts = static_cast<int>(row.integer(5));
  record.wall_time_limit = row.real(6);
  record.job_id = row.optional_integer(7);
  record.worker = row.optional_text(8);
  record.queued_at = row.real(9);
  record.started_at = row.optional_real(10);
  record.finished_at = row.optional_real(11);
  record.error = row.optional_text(12);
  record.grid_point = nlohmann::ordered_json::parse(row.text(13));
  record.replicate = static_cast<int>(row.integer(14));
  record.outcome = row.optional_text(15);
  record.restitution = row.optional_real(16);
  record.retained_mass_fraction = row.optional_real(17);
  record.fragment_count = row.optional_integer(18);
  record.damage_ratio = row.optional_real(19);
  record.fractured_on_wall = optional_flag(row, 20);
  record.small_strain_exceeded = optional_flag(row, 21);
  return record;
}

// A result row; its data file where it lies under `data_directory` now.
ResultRecord result_from(const SqliteStatement& row, const std::filesystem::path& data_directory) {
  ResultRecord record;
  record.case_id = row.integer(0);
  record.hash = row.text(1);
  record.grid_point = nlohmann::ordered_json::parse(row.text(2));
  record.replicate = static_cast<int>(row.integer(3));
  record.attempt = static_cast<int>(row.integer(4));
  record.outcome = row.text(5);
  record.restitution = row.optional_real(6);
  record.largest_fragment_share = row.optional_real(7);
  record.fragment_count = row.optional_integer(8);
  record.retained_mass_fraction = row.optional_real(9);
  record.reentrained_mass_fraction = row.optional_real(10);
  record.damage_ratio = row.optional_real(11);
  record.fractured_on_wall = optional_flag(row, 12);
  record.small_strain_exceeded = optional_flag(row, 13);
  record.energy_per_contact = row.optional_real(14);
  record.energy_over_rolling = row.optional_real(15);
  record.initial_contacts = row.optional_integer(16);
  record.impact_energy = row.optional_real(17);
  record.wall_clock_seconds = row.optional_real(18);
  if (const auto stored = row.optional_text(19)) record.data_file = data_path_on_disk(data_directory, *stored);
  record.committed_at = row.real(20);
  return record;
}

// The SQL condition of a case filter on `sc`, `c` and `r` (kCaseColumns), and its parameters in order.
struct FilterClause {
  std::string sql = "sc.study_id = ?";
  std::vector<std::string> texts;

  FilterClause(const CaseFilter& filter) {
    if (filter.status) add(" AND c.status = ?", std::string(to_string(*filter.status)));
    if (filter.outcome) add(" AND r.outcome = ?", *filter.outcome);
    if (filter.grid_keys)
      add(" AND sc.grid_key IN (SELECT value FROM json_each(?))", nlohmann::json(*filter.grid_keys).dump());
  }
  void add(const char* condition, std::string text) {
    sql += condition;
    texts.push_back(std::move(text));
  }
  // Binds the study and the texts from position 1; returns the next free position.
  int bind(SqliteStatement& statement, std::int64_t study_id) const {
    int index = 1;
    statement.bind(index++, study_id);
    for (const auto& text : texts) statement.bind(index++, text);
    return index;
  }
};

}  // namespace

std::size_t Store::claimable_cases() {
  auto db = read();
  return count(
      db->prepare("SELECT count(*) FROM cases c WHERE c.status = 'queued' AND EXISTS "
                  "(SELECT 1 FROM study_cases sc JOIN studies s ON s.id = sc.study_id "
                  " WHERE sc.case_id = c.id AND s.status = 'active')"));
}

Page<StudyRecord> Store::studies(const PageRequest& page) {
  auto db = read();
  Page<StudyRecord> result;
  result.total = count(db->prepare("SELECT count(*) FROM studies"));
  auto statement = db->prepare(std::string(kStudyColumns) + "ORDER BY s.id DESC LIMIT ? OFFSET ?");
  statement.bind_all(page.limit, page.offset);
  while (statement.step()) result.items.push_back(study_from(statement));
  return result;
}

std::optional<StudyRecord> Store::study(std::int64_t study_id) {
  auto db = read();
  auto statement = db->prepare(std::string(kStudyColumns) + "WHERE s.id = ?");
  statement.bind_all(study_id);
  if (!statement.step()) return std::nullopt;
  return study_from(statement);
}

std::optional<StudyProgress> Store::progress(std::int64_t study_id) {
  auto db = read();
  auto statement = db->prepare(
      "SELECT queued, running, done, failed, cancelled, first_started_at, last_finished_at, finished_here "
      "FROM study_summaries WHERE study_id = ?");
  statement.bind_all(study_id);
  if (!statement.step()) return std::nullopt;

  StudyProgress progress;
  progress.study_id = study_id;
  int column = 0;
  for (const auto status :
       {CaseStatus::queued, CaseStatus::running, CaseStatus::done, CaseStatus::failed, CaseStatus::cancelled}) {
    const auto n = static_cast<std::size_t>(statement.integer(column++));
    progress.by_status[std::string(to_string(status))] = n;
    progress.total += n;
  }
  progress.first_started_at = statement.optional_real(5);
  progress.last_finished_at = statement.optional_real(6);
  const std::size_t remaining = progress.by_status["queued"] + progress.by_status["running"];
  auto groups = db->prepare(
      "SELECT count(*), count(*) FILTER (WHERE g.state = 'searching' AND s.status = 'active') "
      "FROM search_groups g JOIN studies s ON s.id = g.study_id WHERE g.study_id = ?");
  groups.bind_all(study_id);
  groups.step();
  progress.search_groups = static_cast<std::size_t>(groups.integer(0));
  progress.searching_groups = static_cast<std::size_t>(groups.integer(1));
  progress.complete = remaining == 0 && progress.searching_groups == 0;
  // The rate counts the cases finished for this study since it was created; a case finished for an
  // earlier study costs nothing here and is left out.
  const auto finished = static_cast<std::size_t>(statement.integer(7));
  if (progress.first_started_at && finished > 0) {
    const double end = progress.complete && progress.last_finished_at ? *progress.last_finished_at : unix_seconds();
    const double elapsed = std::max(end - *progress.first_started_at, 1e-3);
    progress.cases_per_hour = 3600.0 * static_cast<double>(finished) / elapsed;
    progress.seconds_left = static_cast<double>(remaining) / progress.cases_per_hour * 3600.0;
  }
  return progress;
}

std::optional<StudyVersions> Store::study_versions(std::int64_t study_id) {
  auto db = read();
  auto statement = db->prepare("SELECT case_state_version, result_set_version FROM study_summaries WHERE study_id = ?");
  statement.bind_all(study_id);
  if (!statement.step()) return std::nullopt;
  return StudyVersions{statement.integer(0), statement.integer(1)};
}

Page<CaseRecord> Store::cases(std::int64_t study_id, std::optional<CaseStatus> status, const PageRequest& page) {
  return cases(study_id, CaseFilter{status, std::nullopt, std::nullopt}, page);
}

Page<CaseRecord> Store::cases(std::int64_t study_id, const CaseFilter& filter, const PageRequest& page) {
  auto db = read();
  const FilterClause where(filter);
  Page<CaseRecord> result;
  // The count joins only the tables its conditions read: 100,000 rows of study_cases alone count in
  // a few milliseconds, joined with cases and results in a few hundred; without a condition it is
  // the study's summary row.
  const bool unfiltered = !filter.status && !filter.outcome && !filter.grid_keys;
  const std::string from = std::string("FROM study_cases sc ") +
                           (filter.status ? "JOIN cases c ON c.id = sc.case_id " : "") +
                           (filter.outcome ? "JOIN results r ON r.case_id = sc.case_id " : "") + "WHERE ";
  auto total = db->prepare(unfiltered ? "SELECT queued + running + done + failed + cancelled FROM study_summaries "
                                        "WHERE study_id = ?"
                                      : "SELECT count(*) " + from + where.sql);
  where.bind(total, study_id);
  result.total = total.step() ? static_cast<std::size_t>(total.integer(0)) : 0;
  auto statement =
      db->prepare(std::string(kCaseColumns) + "WHERE " + where.sql + " ORDER BY sc.position LIMIT ? OFFSET ?");
  const int next = where.bind(statement, study_id);
  statement.bind(next, page.limit);
  statement.bind(next + 1, page.offset);
  while (statement.step()) result.items.push_back(case_from(statement));
  return result;
}

Page<ResultRecord> Store::results(std::int64_t study_id, std::optional<std::string> outcome, const PageRequest& page) {
  auto db = read();
  const std::string filter = outcome ? " AND r.outcome = ?" : "";
  const std::string from =
      "FROM study_cases sc JOIN results r ON r.case_id = sc.case_id JOIN cases c ON c.id = sc.case_id "
      "WHERE sc.study_id = ?" +
      filter;
  Page<ResultRecord> result;
  auto total = db->prepare("SELECT count(*) " + from);
  total.bind(1, study_id);
  if (outcome) total.bind(2, *outcome);
  result.total = count(std::move(total));
  auto statement = db->prepare(
      "SELECT r.case_id, c.hash, sc.grid_point, sc.replicate, r.attempt, r.outcome, r.restitution, "
      "r.largest_fragment_share, r.fragment_count, r.retained_mass_fraction, r.reentrained_mass_fraction, "
      "r.damage_ratio, r.fractured_on_wall, r.small_strain_exceeded, r.energy_per_contact, r.energy_over_rolling, "
      "r.initial_contacts, r.impact_energy, r.wall_clock_seconds, r.data_file, r.committed_at " +
      from + " ORDER BY sc.position LIMIT ? OFFSET ?");
  int index = 1;
  statement.bind(index++, study_id);
  if (outcome) statement.bind(index++, *outcome);
  statement.bind(index++, page.limit);
  statement.bind(index, page.offset);
  while (statement.step()) result.items.push_back(result_from(statement, data_directory_));
  return result;
}

std::optional<CaseDetail> Store::case_detail(std::int64_t case_id) {
  auto db = read();
  auto statement = db->prepare(std::string(kCaseColumns) + "WHERE c.id = ? ORDER BY sc.study_id LIMIT 1");
  statement.bind_all(case_id);
  if (!statement.step()) return std::nullopt;
  CaseDetail detail;
  detail.record = case_from(statement);

  auto document = db->prepare("SELECT document FROM cases WHERE id = ?");
  document.bind_all(case_id);
  document.step();
  detail.document = nlohmann::ordered_json::parse(document.text(0));

  auto attempts = db->prepare(
      "SELECT attempt, job_id, worker, started_at, ended_at, outcome, error FROM attempts WHERE case_id = ? "
      "ORDER BY attempt");
  attempts.bind_all(case_id);
  while (attempts.step()) {
    detail.attempts.push_back({static_cast<int>(attempts.integer(0)), attempts.optional_integer(1),
                               attempts.optional_text(2), attempts.real(3), attempts.optional_real(4),
                               attempts.optional_text(5), attempts.optional_text(6)});
  }

  auto result =
      db->prepare("SELECT document, data_file, data_file_size, data_file_sha256 FROM results WHERE case_id = ?");
  result.bind_all(case_id);
  if (result.step()) {
    detail.result = nlohmann::ordered_json::parse(result.text(0));
    if (const auto stored = result.optional_text(1)) detail.data_file = data_path_on_disk(data_directory_, *stored);
    detail.data_file_digest = {result.optional_integer(2).value_or(-1), result.optional_text(3).value_or("")};
  }

  auto fragments = db->prepare(
      "SELECT rank, primaries, mass, on_wall, normal_velocity, radius_of_gyration FROM fragments WHERE case_id = ? "
      "ORDER BY rank");
  fragments.bind_all(case_id);
  while (fragments.step()) {
    detail.fragments.push_back({static_cast<int>(fragments.integer(0)), fragments.integer(1), fragments.real(2),
                                fragments.integer(3) != 0, fragments.optional_real(4), fragments.optional_real(5)});
  }
  return detail;
}

std::vector<JobRecord> Store::jobs(std::size_t limit) {
  auto db = read();
  auto statement = db->prepare(
      "SELECT id, command, ranks, pid, started_at, ended_at, exit_status, note FROM jobs ORDER BY id DESC LIMIT ?");
  statement.bind_all(limit);
  std::vector<JobRecord> jobs;
  while (statement.step()) {
    jobs.push_back({statement.integer(0), statement.text(1), static_cast<int>(statement.integer(2)),
                    statement.optional_integer(3), statement.real(4), statement.optional_real(5),
                    statement.optional_integer(6), statement.optional_text(7)});
  }
  return jobs;
}

std::vector<StoredDataFile> Store::data_files(const std::vector<std::string>& hashes) {
  auto db = read();
  auto statement = db->prepare(
      "SELECT r.data_file, r.data_file_size, r.data_file_sha256 FROM cases c JOIN results r ON r.case_id = c.id "
      "WHERE c.hash = ? AND c.status = 'done' AND r.data_file IS NOT NULL");
  std::vector<StoredDataFile> files;
  for (const auto& hash : hashes) {
    statement.reset();
    statement.bind_all(hash);
    if (statement.step())
      files.push_back({hash,
                       data_path_on_disk(data_directory_, statement.text(0)),
                       {statement.optional_integer(1).value_or(-1), statement.optional_text(2).value_or("")}});
  }
  return files;
}

std::vector<std::string> Store::study_case_hashes(const std::string& study_hash) {
  auto db = read();
  auto statement = db->prepare(
      "SELECT c.hash FROM studies s JOIN study_cases sc ON sc.study_id = s.id JOIN cases c ON c.id = sc.case_id "
      "WHERE s.hash = ? ORDER BY sc.position");
  statement.bind_all(study_hash);
  std::vector<std::string> hashes;
  while (statement.step()) hashes.push_back(statement.text(0));
  return hashes;
}

}  // namespace aerobreak
