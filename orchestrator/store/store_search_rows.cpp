#include "orchestrator/store/store_search_rows.hpp"

#include "engine/impact/case_inputs.hpp"

namespace aerobreak {

void link_study_cases(SqliteDatabase& db, std::int64_t study_id, const std::vector<StudySubmission::Case>& cases,
                      std::int64_t first_position, const CaseSettings& settings, SubmissionReceipt& receipt) {
  auto find_case = db.prepare("SELECT id, status FROM cases WHERE hash = ?");
  auto insert_case = db.prepare(
      "INSERT INTO cases (hash, document, primaries, status, max_attempts, wall_time_limit, queued_at) "
      "VALUES (?, ?, ?, 'queued', ?, ?, ?)");
  auto requeue_case = db.prepare("UPDATE cases SET status = 'queued', queued_at = ? WHERE id = ?");
  auto link = db.prepare(
      "INSERT OR IGNORE INTO study_cases (study_id, case_id, position, grid_point, grid_key, replicate, search_group, "
      "search_round) VALUES (?, ?, ?, ?, ?, ?, ?, ?)");
  std::int64_t position = first_position;
  for (const auto& study_case : cases) {
    std::int64_t case_id = 0;
    find_case.reset();
    find_case.bind_all(study_case.hash);
    if (find_case.step()) {
      case_id = find_case.integer(0);
      const std::string status = find_case.text(1);
      if (status == "done") ++receipt.already_done;
      if (status == "cancelled") {
        requeue_case.reset();
        requeue_case.bind_all(settings.now, case_id).run();
        ++receipt.requeued;
      }
    } else {
      insert_case.reset();
      insert_case.bind_all(study_case.hash, study_case.document.dump(), read_case_inputs(study_case.document).primaries,
                           settings.max_attempts, settings.wall_time_limit, settings.now);
      insert_case.run();
      case_id = db.last_insert_id();
      ++receipt.new_cases;
    }
    link.reset();
    link.bind_all(study_id, case_id, position++, study_case.grid_point.dump(), study_case.grid_key,
                  study_case.replicate, study_case.search_group, study_case.search_round);
    link.run();
  }
}

void insert_search_groups(SqliteDatabase& db, std::int64_t study_id,
                          const std::vector<StudySubmission::SearchGroup>& groups, double now) {
  auto group = db.prepare(
      "INSERT INTO search_groups (study_id, position, group_point, state, rounds, cases, updated_at) "
      "VALUES (?, ?, ?, 'searching', 1, ?, ?)");
  auto round =
      db.prepare("INSERT INTO search_rounds (study_id, position, round, decided_at, plan) VALUES (?, ?, 0, ?, ?)");
  for (const auto& g : groups) {
    group.reset();
    group.bind_all(study_id, g.position, g.group_point.dump(), g.cases, now).run();
    round.reset();
    round.bind_all(study_id, g.position, now, g.round_zero.dump()).run();
  }
}

}  // namespace aerobreak
