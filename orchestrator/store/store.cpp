#include "orchestrator/store/store.hpp"

#include <chrono>
#include <stdexcept>

#include "orchestrator/store/data_paths.hpp"
#include "orchestrator/store/migrations.hpp"
#include "orchestrator/store/statistics_functions.hpp"
#include "orchestrator/store/store_file.hpp"
#include "orchestrator/store/store_read_connection.hpp"
#include "orchestrator/store/store_search_rows.hpp"
#include "orchestrator/store/store_summaries.hpp"

namespace aerobreak {

double unix_seconds() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

Store::Store(const std::filesystem::path& file, Access access, const std::filesystem::path& data_directory)
    : file_(file),
      data_directory_(
          std::filesystem::absolute(data_directory.empty() ? default_data_directory(file) : data_directory)) {
  if (access == Access::reader) {
    open_for_reading();
    return;
  }
  // Examined read-only before it is locked, migrated or switched to WAL: a file that is not empty
  // and not an aerobreak store this aerobreak can upgrade is refused unchanged.
  const StoreFileState state = inspect_store_file(file);
  if (state.kind == StoreFileState::Kind::foreign || state.kind == StoreFileState::Kind::newer)
    throw StoreFileRefused(state.problem + "; a store is a new or empty file, or an aerobreak store");
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  lock_.emplace(file);
  writer_ = std::make_unique<SqliteDatabase>(file);
  // WAL: readers never block the writer nor the writer them; synchronous=FULL makes every commit
  // durable before the call returns, so that a result acknowledged in the store survives a crash
  // of the orchestrator or of the machine.
  writer_->execute("PRAGMA journal_mode = WAL");
  writer_->execute("PRAGMA synchronous = FULL");
  opened_at_version_ = migrate_store(*writer_);
}

void Store::open_for_reading() {
  const StoreFileState state = inspect_store_file(file_);
  switch (state.kind) {
    case StoreFileState::Kind::absent:
      throw std::runtime_error("no store file " + file_.string());
    case StoreFileState::Kind::empty:
      throw StoreFileRefused("the file " + file_.string() + " is empty: no store yet");
    case StoreFileState::Kind::foreign:
    case StoreFileState::Kind::newer:
      throw StoreFileRefused(state.problem);
    case StoreFileState::Kind::store:
      break;
  }
  if (state.version != latest_store_version())
    throw std::runtime_error("the store " + file_.string() + " has schema version " + std::to_string(state.version) +
                             ", this aerobreak reads version " + std::to_string(latest_store_version()) +
                             ": open it once with `aerobreak serve` or `aerobreak run` of this version to upgrade it");
  writer_ = std::make_unique<SqliteDatabase>(file_, SqliteDatabase::Mode::read_only);
  opened_at_version_ = state.version;
}

Store::~Store() = default;

Store::ReadConnection Store::read() {
  {
    std::lock_guard lock(pool_mutex_);
    if (!idle_readers_.empty()) {
      auto db = std::move(idle_readers_.back());
      idle_readers_.pop_back();
      return ReadConnection(*this, std::move(db));
    }
  }
  auto db = std::make_unique<SqliteDatabase>(file_, SqliteDatabase::Mode::read_only);
  add_statistics_functions(*db);
  return ReadConnection(*this, std::move(db));
}

int Store::schema_version() {
  auto db = read();
  auto statement = db->prepare("PRAGMA user_version");
  statement.step();
  return static_cast<int>(statement.integer(0));
}

namespace {

// Done cases whose data file was lost or damaged, and whose recomputation was asked for, go back
// to the queue. Their results and fragments stay (served as before) until commit_result replaces
// them. Returns how many.
std::size_t requeue_for_recompute(SqliteDatabase& db, const std::vector<std::string>& hashes, double now) {
  auto requeue = db.prepare(
      "UPDATE cases SET status = 'queued', queued_at = ?, finished_at = NULL, "
      "error = 'its data file was lost or damaged: computed again (its result is kept until then)' "
      "WHERE hash = ? AND status = 'done'");
  std::size_t requeued = 0;
  for (const auto& hash : hashes) {
    requeue.reset();
    requeue.bind_all(now, hash).run();
    requeued += static_cast<std::size_t>(db.changes());
  }
  return requeued;
}

// The result a case had before (one queued again to recompute its data file), dropped in the
// transaction that stores its replacement.
void drop_result(SqliteDatabase& db, std::int64_t case_id) {
  for (const char* sql : {"DELETE FROM fragments WHERE case_id = ?", "DELETE FROM results WHERE case_id = ?"})
    db.prepare(sql).bind_all(case_id).run();
}

// A study submitted again: wanted again if it was cancelled, and so are its cancelled cases.
// Returns the cases queued again.
std::size_t resume_study(SqliteDatabase& db, std::int64_t study_id, double now) {
  db.prepare("UPDATE studies SET status = 'active', cancelled_at = NULL WHERE id = ? AND status = 'cancelled'")
      .bind_all(study_id)
      .run();
  if (db.changes() == 0) return 0;
  db.prepare(
        "UPDATE cases SET status = 'queued', queued_at = ? WHERE status = 'cancelled' AND id IN "
        "(SELECT case_id FROM study_cases WHERE study_id = ?)")
      .bind_all(now, study_id)
      .run();
  return static_cast<std::size_t>(db.changes());
}

std::size_t done_cases(SqliteDatabase& db, std::int64_t study_id) {
  auto count = db.prepare(
      "SELECT count(*) FROM study_cases sc JOIN cases c ON c.id = sc.case_id WHERE sc.study_id = ? AND c.status = "
      "'done'");
  count.bind_all(study_id);
  count.step();
  return static_cast<std::size_t>(count.integer(0));
}

}  // namespace

SubmissionReceipt Store::submit_study(const StudySubmission& submission) {
  std::lock_guard lock(write_mutex_);
  SqliteTransaction transaction(*writer_);
  const double now = unix_seconds();
  SubmissionReceipt receipt;
  receipt.cases = submission.cases.size();
  receipt.recomputed = requeue_for_recompute(*writer_, submission.recompute, now);

  auto existing = writer_->prepare("SELECT id FROM studies WHERE hash = ?");
  existing.bind_all(submission.hash);
  if (existing.step()) {
    receipt.study_id = existing.integer(0);
    receipt.existing_study = true;
    receipt.requeued = resume_study(*writer_, receipt.study_id, now);
    receipt.already_done = done_cases(*writer_, receipt.study_id);
  } else {
    insert_study(submission, now, receipt);
  }
  transaction.commit();
  return receipt;
}

void Store::insert_study(const StudySubmission& submission, double now, SubmissionReceipt& receipt) {
  auto insert_study = writer_->prepare(
      "INSERT INTO studies (hash, name, description, document, status, max_attempts, case_wall_time, created_at) "
      "VALUES (?, ?, ?, ?, 'active', ?, ?, ?)");
  insert_study.bind_all(submission.hash, submission.name, submission.description, submission.document.dump(),
                        submission.max_attempts, submission.case_wall_time, now);
  insert_study.run();
  receipt.study_id = writer_->last_insert_id();

  link_study_cases(*writer_, receipt.study_id, submission.cases, 0,
                   {submission.max_attempts, submission.case_wall_time, now}, receipt);
  insert_search_groups(*writer_, receipt.study_id, submission.search_groups, now);
}

std::optional<ClaimedCase> Store::claim_next_case(std::int64_t job_id, const std::string& worker) {
  std::lock_guard lock(write_mutex_);
  SqliteTransaction transaction(*writer_);
  auto next = writer_->prepare(
      "SELECT c.id, c.attempts, c.document, c.wall_time_limit, c.hash FROM cases c WHERE c.status = 'queued' AND "
      "EXISTS "
      "(SELECT 1 FROM study_cases sc JOIN studies s ON s.id = sc.study_id "
      " WHERE sc.case_id = c.id AND s.status = 'active') ORDER BY c.id LIMIT 1");
  if (!next.step()) return std::nullopt;
  ClaimedCase assignment;
  assignment.case_id = next.integer(0);
  assignment.attempt = static_cast<int>(next.integer(1)) + 1;
  assignment.document = nlohmann::ordered_json::parse(next.text(2));
  assignment.wall_time_limit = next.real(3);
  assignment.hash = next.text(4);
  const double now = unix_seconds();
  writer_
      ->prepare(
          "UPDATE cases SET status = 'running', attempts = ?, job_id = ?, worker = ?, started_at = ? WHERE id = ?")
      .bind_all(assignment.attempt, job_id, worker, now, assignment.case_id)
      .run();
  writer_->prepare("INSERT INTO attempts (case_id, attempt, job_id, worker, started_at) VALUES (?, ?, ?, ?, ?)")
      .bind_all(assignment.case_id, assignment.attempt, job_id, worker, now)
      .run();
  transaction.commit();
  return assignment;
}

void Store::record_worker(std::int64_t case_id, int attempt, const std::string& worker) {
  std::lock_guard lock(write_mutex_);
  SqliteTransaction transaction(*writer_);
  writer_->prepare("UPDATE cases SET worker = ? WHERE id = ? AND attempts = ? AND status = 'running'")
      .bind_all(worker, case_id, attempt)
      .run();
  writer_->prepare("UPDATE attempts SET worker = ? WHERE case_id = ? AND attempt = ?")
      .bind_all(worker, case_id, attempt)
      .run();
  transaction.commit();
}

namespace {

std::optional<double> optional_number(const nlohmann::ordered_json& value) {
  return value.is_number() ? std::optional(value.get<double>()) : std::nullopt;
}

const nlohmann::ordered_json& member(const nlohmann::ordered_json& object, const char* key) {
  static const nlohmann::ordered_json null;
  if (!object.is_object()) return null;
  const auto found = object.find(key);
  return found == object.end() ? null : *found;
}

std::optional<std::int64_t> optional_integer(const nlohmann::ordered_json& value) {
  return value.is_number_integer() ? std::optional(value.get<std::int64_t>()) : std::nullopt;
}

std::optional<int> optional_flag(const nlohmann::ordered_json& value) {
  return value.is_boolean() ? std::optional(value.get<bool>() ? 1 : 0) : std::nullopt;
}

// The summary columns of a result document (schemas/result.schema.json); the document itself is
// stored whole beside them.
void insert_result(SqliteDatabase& db, std::int64_t case_id, int attempt, const nlohmann::ordered_json& result,
                   const std::string& data_file, double wall_clock_seconds, const DataFileDigest& digest, double now) {
  const auto& outcome = member(result, "outcome");
  const auto& outcome_class = member(outcome, "class");
  if (!outcome_class.is_string()) throw std::invalid_argument("result document without /outcome/class");
  const auto& dimensionless = member(result, "dimensionless");
  const auto& small_strain = member(member(result, "validity"), "small_strain");
  auto statement = db.prepare(
      "INSERT INTO results (case_id, attempt, outcome, restitution, largest_fragment_share, fragment_count, "
      "retained_mass_fraction, reentrained_mass_fraction, damage_ratio, fractured_on_wall, small_strain_exceeded, "
      "energy_per_contact, energy_over_rolling, initial_contacts, impact_energy, wall_clock_seconds, data_file, "
      "document, committed_at, data_file_size, data_file_sha256) "
      "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
  statement.bind_all(
      case_id, attempt, outcome_class.get<std::string>(),
      optional_number(member(member(outcome, "restitution"), "normal")),
      optional_number(member(outcome, "largest_fragment_share")), optional_integer(member(outcome, "fragment_count")),
      optional_number(member(outcome, "retained_mass_fraction")),
      optional_number(member(outcome, "reentrained_mass_fraction")), optional_number(member(outcome, "damage_ratio")),
      optional_flag(member(outcome, "fractured_on_wall")),
      small_strain.is_boolean() ? std::optional(small_strain.get<bool>() ? 0 : 1) : std::nullopt,
      optional_number(member(dimensionless, "energy_per_contact")),
      optional_number(member(dimensionless, "energy_over_rolling")),
      optional_integer(member(dimensionless, "initial_contacts")),
      optional_number(member(member(result, "setup"), "impact_kinetic_energy")), wall_clock_seconds,
      data_file.empty() ? std::optional<std::string>() : std::optional(data_file), result.dump(), now,
      digest.size >= 0 && !data_file.empty() ? std::optional(digest.size) : std::nullopt,
      digest.sha256.empty() || data_file.empty() ? std::nullopt : std::optional(digest.sha256));
  statement.run();

  auto fragment = db.prepare(
      "INSERT INTO fragments (case_id, rank, primaries, mass, on_wall, normal_velocity, radius_of_gyration) "
      "VALUES (?, ?, ?, ?, ?, ?, ?)");
  int rank = 0;
  for (const auto& entry : member(member(result, "fragments"), "list")) {
    fragment.reset();
    fragment.bind_all(case_id, rank++, member(entry, "size").get<std::int64_t>(), member(entry, "mass").get<double>(),
                      member(entry, "on_wall").get<bool>() ? 1 : 0, optional_number(member(entry, "normal_velocity")),
                      optional_number(member(entry, "radius_of_gyration")));
    fragment.run();
  }
}

// A cluster file's N is not in its case's document (the case's primaries column stays null when
// it is stored): its first result tells it, as its fragments' primaries together, since every
// primary is in exactly one fragment.
void fill_primaries_from_fragments(SqliteDatabase& db, std::int64_t case_id) {
  db.prepare(
        "UPDATE cases SET primaries = (SELECT sum(primaries) FROM fragments WHERE case_id = ?1) "
        "WHERE id = ?1 AND primaries IS NULL")
      .bind_all(case_id)
      .run();
}

}  // namespace

bool Store::commit_result(std::int64_t case_id, int attempt, const nlohmann::ordered_json& result,
                          const std::string& data_file, double wall_clock_seconds, const DataFileDigest& digest) {
  std::lock_guard lock(write_mutex_);
  SqliteTransaction transaction(*writer_);
  const double now = unix_seconds();
  writer_
      ->prepare(
          "UPDATE cases SET status = 'done', finished_at = ?, error = NULL "
          "WHERE id = ? AND status = 'running' AND attempts = ?")
      .bind_all(now, case_id, attempt)
      .run();
  if (writer_->changes() != 1) return false;
  drop_result(*writer_, case_id);
  insert_result(*writer_, case_id, attempt, result, stored_data_path(data_directory_, data_file), wall_clock_seconds,
                digest, now);
  fill_primaries_from_fragments(*writer_, case_id);
  writer_->prepare("UPDATE attempts SET ended_at = ?, outcome = 'done' WHERE case_id = ? AND attempt = ?")
      .bind_all(now, case_id, attempt)
      .run();
  transaction.commit();
  return true;
}

std::optional<CaseStatus> Store::record_failure(std::int64_t case_id, int attempt, AttemptEnd end,
                                                const std::string& error) {
  std::lock_guard lock(write_mutex_);
  SqliteTransaction transaction(*writer_);
  auto current =
      writer_->prepare("SELECT failures, max_attempts FROM cases WHERE id = ? AND status = 'running' AND attempts = ?");
  current.bind_all(case_id, attempt);
  if (!current.step()) return std::nullopt;
  const auto failures = current.integer(0) + 1;
  // An invalid case fails the same way every time: retrying it would only waste a worker.
  const bool give_up = end == AttemptEnd::invalid || failures >= current.integer(1);
  const CaseStatus status = give_up ? CaseStatus::failed : CaseStatus::queued;
  const double now = unix_seconds();
  writer_
      ->prepare(
          "UPDATE cases SET status = ?, failures = ?, error = ?, finished_at = ?, queued_at = "
          "CASE WHEN ? THEN queued_at ELSE ? END WHERE id = ?")
      .bind_all(to_string(status), failures, error, give_up ? std::optional(now) : std::nullopt, give_up ? 1 : 0, now,
                case_id)
      .run();
  writer_->prepare("UPDATE attempts SET ended_at = ?, outcome = ?, error = ? WHERE case_id = ? AND attempt = ?")
      .bind_all(now, to_string(end), error, case_id, attempt)
      .run();
  transaction.commit();
  return status;
}

std::size_t Store::requeue_job(std::int64_t job_id, const std::string& reason, bool counts_as_failure) {
  if (!counts_as_failure) return requeue_running("job_id = " + std::to_string(job_id), reason);
  std::vector<std::pair<std::int64_t, int>> running;
  {
    auto db = read();
    auto statement = db->prepare("SELECT id, attempts FROM cases WHERE status = 'running' AND job_id = ?");
    statement.bind_all(job_id);
    while (statement.step()) running.emplace_back(statement.integer(0), static_cast<int>(statement.integer(1)));
  }
  std::size_t requeued = 0;
  for (const auto& [case_id, attempt] : running)
    if (record_failure(case_id, attempt, AttemptEnd::lost, reason) == CaseStatus::queued) ++requeued;
  return requeued;
}

std::size_t Store::requeue_interrupted() { return requeue_running("1", "the orchestrator stopped while the case ran"); }

bool Store::requeue_attempt(std::int64_t case_id, int attempt, const std::string& reason) {
  return requeue_running("id = " + std::to_string(case_id) + " AND attempts = " + std::to_string(attempt), reason) == 1;
}

std::size_t Store::requeue_running(const std::string& condition, const std::string& reason) {
  std::lock_guard lock(write_mutex_);
  SqliteTransaction transaction(*writer_);
  const double now = unix_seconds();
  writer_
      ->prepare(
          "UPDATE attempts SET ended_at = ?, outcome = 'interrupted', error = ? WHERE ended_at IS NULL AND "
          "(case_id, attempt) IN (SELECT id, attempts FROM cases WHERE status = 'running' AND " +
          condition + ")")
      .bind_all(now, reason)
      .run();
  writer_->prepare("UPDATE cases SET status = 'queued', queued_at = ? WHERE status = 'running' AND " + condition)
      .bind_all(now)
      .run();
  const auto requeued = static_cast<std::size_t>(writer_->changes());
  transaction.commit();
  return requeued;
}

std::int64_t Store::start_job(const std::string& command, int ranks) {
  std::lock_guard lock(write_mutex_);
  writer_->prepare("INSERT INTO jobs (command, ranks, started_at) VALUES (?, ?, ?)")
      .bind_all(command, ranks, unix_seconds())
      .run();
  return writer_->last_insert_id();
}

void Store::job_started(std::int64_t job_id, std::int64_t pid, const nlohmann::ordered_json& hosts) {
  std::lock_guard lock(write_mutex_);
  writer_->prepare("UPDATE jobs SET pid = ?, hosts = ? WHERE id = ?").bind_all(pid, hosts.dump(), job_id).run();
}

void Store::end_job(std::int64_t job_id, int exit_status, const std::string& note) {
  std::lock_guard lock(write_mutex_);
  writer_->prepare("UPDATE jobs SET ended_at = ?, exit_status = ?, note = ? WHERE id = ? AND ended_at IS NULL")
      .bind_all(unix_seconds(), exit_status, note, job_id)
      .run();
}

std::size_t Store::close_orphaned_jobs() {
  std::lock_guard lock(write_mutex_);
  writer_->prepare("UPDATE jobs SET ended_at = ?, note = 'its orchestrator stopped' WHERE ended_at IS NULL")
      .bind_all(unix_seconds())
      .run();
  return static_cast<std::size_t>(writer_->changes());
}

bool Store::cancel_study(std::int64_t study_id) {
  std::lock_guard lock(write_mutex_);
  SqliteTransaction transaction(*writer_);
  const double now = unix_seconds();
  writer_->prepare("UPDATE studies SET status = 'cancelled', cancelled_at = ? WHERE id = ? AND status = 'active'")
      .bind_all(now, study_id)
      .run();
  if (writer_->changes() != 1) return false;
  writer_
      ->prepare(
          "UPDATE cases SET status = 'cancelled', finished_at = ? WHERE status = 'queued' "
          "AND id IN (SELECT case_id FROM study_cases WHERE study_id = ?) "
          "AND NOT EXISTS (SELECT 1 FROM study_cases sc JOIN studies s ON s.id = sc.study_id "
          "                WHERE sc.case_id = cases.id AND s.status = 'active')")
      .bind_all(now, study_id)
      .run();
  transaction.commit();
  return true;
}

void Store::rebuild_summaries() {
  std::lock_guard lock(write_mutex_);
  SqliteTransaction transaction(*writer_);
  rebuild_store_summaries(*writer_);
  transaction.commit();
}

}  // namespace aerobreak
