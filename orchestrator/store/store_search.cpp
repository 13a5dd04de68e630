// The store's side of adaptive searches (docs/ADAPTIVE.md): which groups are due a round, the
// rounds and states decided, and what the REST API shows of them.
#include "orchestrator/store/store.hpp"
#include "orchestrator/store/store_read_connection.hpp"
#include "orchestrator/store/store_search_rows.hpp"

namespace aerobreak {
namespace {

using Json = nlohmann::ordered_json;

std::vector<SearchGroupWork::Case> group_cases(SqliteDatabase& db, std::int64_t study_id, std::int64_t position) {
  auto statement = db.prepare(
      "SELECT sc.grid_point, r.outcome, sc.search_round FROM study_cases sc LEFT JOIN results r ON r.case_id = "
      "sc.case_id "
      "WHERE sc.study_id = ? AND sc.search_group = ? ORDER BY sc.position");
  statement.bind_all(study_id, position);
  std::vector<SearchGroupWork::Case> cases;
  while (statement.step())
    cases.push_back({Json::parse(statement.text(0)), statement.optional_text(1).value_or(""),
                     static_cast<int>(statement.integer(2))});
  return cases;
}

std::vector<SearchRoundRecord> rounds_of(SqliteDatabase& db, std::int64_t study_id, std::int64_t position) {
  auto statement = db.prepare(
      "SELECT round, decided_at, plan FROM search_rounds WHERE study_id = ? AND position = ? ORDER BY round");
  statement.bind_all(study_id, position);
  std::vector<SearchRoundRecord> rounds;
  while (statement.step())
    rounds.push_back({static_cast<int>(statement.integer(0)), statement.real(1), Json::parse(statement.text(2))});
  return rounds;
}

}  // namespace

std::vector<SearchGroupWork> Store::search_work() {
  auto db = read();
  auto due = db->prepare(
      "SELECT g.study_id, g.position, g.group_point, g.rounds, g.cases, s.document FROM search_groups g "
      "JOIN studies s ON s.id = g.study_id WHERE g.state = 'searching' AND s.status = 'active' AND NOT EXISTS "
      "(SELECT 1 FROM study_cases sc JOIN cases c ON c.id = sc.case_id WHERE sc.study_id = g.study_id "
      " AND sc.search_group = g.position AND c.status IN ('queued', 'running', 'cancelled')) "
      "ORDER BY g.study_id, g.position");
  std::vector<SearchGroupWork> work;
  while (due.step()) {
    SearchGroupWork w;
    w.study_id = due.integer(0);
    w.position = due.integer(1);
    w.group_point = Json::parse(due.text(2));
    w.rounds = static_cast<int>(due.integer(3));
    w.cases = static_cast<int>(due.integer(4));
    w.study_document = Json::parse(due.text(5));
    work.push_back(std::move(w));
  }
  for (auto& w : work) w.finished = group_cases(*db, w.study_id, w.position);
  return work;
}

bool Store::record_search_decision(const SearchDecision& decision) {
  std::lock_guard lock(write_mutex_);
  SqliteTransaction transaction(*writer_);
  auto group = writer_->prepare(
      "SELECT g.rounds, s.max_attempts, s.case_wall_time, (SELECT coalesce(max(position), -1) + 1 FROM study_cases "
      "WHERE study_id = g.study_id) FROM search_groups g JOIN studies s ON s.id = g.study_id "
      "WHERE g.study_id = ? AND g.position = ? AND g.state = 'searching'");
  group.bind_all(decision.study_id, decision.position);
  if (!group.step() || group.integer(0) != decision.round) return false;
  const double now = unix_seconds();
  const CaseSettings settings{static_cast<int>(group.integer(1)), group.real(2), now};
  const std::int64_t first_position = group.integer(3);
  if (!decision.cases.empty()) {
    writer_->prepare("INSERT INTO search_rounds (study_id, position, round, decided_at, plan) VALUES (?, ?, ?, ?, ?)")
        .bind_all(decision.study_id, decision.position, decision.round, now, decision.plan.dump())
        .run();
    SubmissionReceipt receipt;
    link_study_cases(*writer_, decision.study_id, decision.cases, first_position, settings, receipt);
  }
  const int placed_rounds = decision.cases.empty() ? 0 : 1;
  writer_
      ->prepare(
          "UPDATE search_groups SET state = ?, rounds = rounds + ?, cases = cases + ?, estimates = ?, note = ?, "
          "updated_at = ? WHERE study_id = ? AND position = ?")
      .bind_all(decision.state, placed_rounds, decision.cases.size(), decision.estimates.dump(),
                decision.note.empty() ? std::optional<std::string>() : std::optional(decision.note), now,
                decision.study_id, decision.position)
      .run();
  transaction.commit();
  return true;
}

std::vector<SearchGroupRecord> Store::search_groups(std::int64_t study_id, bool history) {
  auto db = read();
  auto statement = db->prepare(
      "SELECT position, group_point, state, rounds, cases, estimates, note, updated_at FROM search_groups "
      "WHERE study_id = ? ORDER BY position");
  statement.bind_all(study_id);
  std::vector<SearchGroupRecord> groups;
  while (statement.step()) {
    SearchGroupRecord g;
    g.position = statement.integer(0);
    g.group_point = Json::parse(statement.text(1));
    g.state = statement.text(2);
    g.rounds = static_cast<int>(statement.integer(3));
    g.cases = static_cast<int>(statement.integer(4));
    g.estimates = Json::parse(statement.text(5));
    g.note = statement.optional_text(6);
    g.updated_at = statement.real(7);
    groups.push_back(std::move(g));
  }
  if (history)
    for (auto& g : groups) g.history = rounds_of(*db, study_id, g.position);
  return groups;
}

}  // namespace aerobreak
