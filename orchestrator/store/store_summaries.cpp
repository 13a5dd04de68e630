#include "orchestrator/store/store_summaries.hpp"

namespace aerobreak {
namespace {

// A study's summary row exists from its creation.
constexpr std::string_view kStudyTrigger = R"sql(
CREATE TRIGGER summaries_after_study_insert AFTER INSERT ON studies
BEGIN
  INSERT INTO study_summaries (study_id) VALUES (NEW.id);
END;
)sql";

// A case linked to a study adds itself as it is now (new, or shared with an earlier study).
constexpr std::string_view kLinkTrigger = R"sql(
CREATE TRIGGER summaries_after_link AFTER INSERT ON study_cases
BEGIN
  UPDATE study_summaries SET
    queued = queued + (c.status = 'queued'),
    running = running + (c.status = 'running'),
    done = done + (c.status = 'done'),
    failed = failed + (c.status = 'failed'),
    cancelled = cancelled + (c.status = 'cancelled'),
    finished_here = finished_here + coalesce(c.status IN ('done', 'failed') AND c.finished_at >= s.created_at, 0),
    first_started_at = coalesce(min(first_started_at, c.started_at), first_started_at, c.started_at),
    last_finished_at = coalesce(max(last_finished_at, c.finished_at), last_finished_at, c.finished_at),
    case_state_version = case_state_version + 1,
    result_set_version = result_set_version + EXISTS (SELECT 1 FROM results WHERE case_id = c.id)
  FROM cases c, studies s
  WHERE c.id = NEW.case_id AND s.id = NEW.study_id AND study_summaries.study_id = NEW.study_id;
  INSERT OR IGNORE INTO grid_point_summaries (study_id, grid_key, position, grid_point)
    VALUES (NEW.study_id, NEW.grid_key, NEW.position, NEW.grid_point);
  UPDATE grid_point_summaries SET
    cases = cases + 1,
    position = min(position, NEW.position),
    stick = stick + coalesce(r.outcome = 'stick', 0),
    bounce = bounce + coalesce(r.outcome = 'bounce', 0),
    break_up = break_up + coalesce(r.outcome = 'break-up', 0),
    undetermined = undetermined + coalesce(r.outcome = 'undetermined', 0),
    failed = failed + (c.status = 'failed')
  FROM cases c LEFT JOIN results r ON r.case_id = c.id
  WHERE c.id = NEW.case_id AND grid_point_summaries.study_id = NEW.study_id
    AND grid_point_summaries.grid_key = NEW.grid_key;
END;
)sql";

// A case that changes status or times moves between the counts of every study that has it. The
// first start and the last finish are those of the cases as they are now (as a query over them
// would give): when the case that held one of them moves it the wrong way (restarted later, its
// finish cleared), that study's value is looked up again, which is rare.
constexpr std::string_view kCaseTrigger = R"sql(
CREATE TRIGGER summaries_after_case_change AFTER UPDATE OF status, started_at, finished_at ON cases
BEGIN
  UPDATE study_summaries SET
    queued = queued + (NEW.status = 'queued') - (OLD.status = 'queued'),
    running = running + (NEW.status = 'running') - (OLD.status = 'running'),
    done = done + (NEW.status = 'done') - (OLD.status = 'done'),
    failed = failed + (NEW.status = 'failed') - (OLD.status = 'failed'),
    cancelled = cancelled + (NEW.status = 'cancelled') - (OLD.status = 'cancelled'),
    finished_here = finished_here
      + coalesce(NEW.status IN ('done', 'failed') AND NEW.finished_at >= s.created_at, 0)
      - coalesce(OLD.status IN ('done', 'failed') AND OLD.finished_at >= s.created_at, 0),
    first_started_at = CASE
      WHEN OLD.started_at = first_started_at AND (NEW.started_at IS NULL OR NEW.started_at > OLD.started_at)
      THEN (SELECT min(c.started_at) FROM study_cases sc JOIN cases c ON c.id = sc.case_id
            WHERE sc.study_id = s.id)
      ELSE coalesce(min(first_started_at, NEW.started_at), first_started_at, NEW.started_at) END,
    last_finished_at = CASE
      WHEN OLD.finished_at = last_finished_at AND (NEW.finished_at IS NULL OR NEW.finished_at < OLD.finished_at)
      THEN (SELECT max(c.finished_at) FROM study_cases sc JOIN cases c ON c.id = sc.case_id
            WHERE sc.study_id = s.id)
      ELSE coalesce(max(last_finished_at, NEW.finished_at), last_finished_at, NEW.finished_at) END,
    case_state_version = case_state_version + 1
  FROM studies s
  WHERE s.id = study_summaries.study_id
    AND study_summaries.study_id IN (SELECT study_id FROM study_cases WHERE case_id = NEW.id);
  UPDATE grid_point_summaries SET failed = failed + (NEW.status = 'failed') - (OLD.status = 'failed')
  FROM study_cases sc
  WHERE NEW.status IS NOT OLD.status AND sc.case_id = NEW.id AND grid_point_summaries.study_id = sc.study_id
    AND grid_point_summaries.grid_key = sc.grid_key;
END;
)sql";

// A result stored, changed (a migration re-classifying outcomes) or removed.
constexpr std::string_view kResultTriggers = R"sql(
CREATE TRIGGER summaries_after_result_insert AFTER INSERT ON results
BEGIN
  UPDATE grid_point_summaries SET
    stick = stick + (NEW.outcome = 'stick'),
    bounce = bounce + (NEW.outcome = 'bounce'),
    break_up = break_up + (NEW.outcome = 'break-up'),
    undetermined = undetermined + (NEW.outcome = 'undetermined')
  FROM study_cases sc
  WHERE sc.case_id = NEW.case_id AND grid_point_summaries.study_id = sc.study_id
    AND grid_point_summaries.grid_key = sc.grid_key;
  UPDATE study_summaries SET result_set_version = result_set_version + 1
  WHERE study_id IN (SELECT study_id FROM study_cases WHERE case_id = NEW.case_id);
END;
CREATE TRIGGER summaries_after_result_update AFTER UPDATE ON results
BEGIN
  UPDATE grid_point_summaries SET
    stick = stick + (NEW.outcome = 'stick') - (OLD.outcome = 'stick'),
    bounce = bounce + (NEW.outcome = 'bounce') - (OLD.outcome = 'bounce'),
    break_up = break_up + (NEW.outcome = 'break-up') - (OLD.outcome = 'break-up'),
    undetermined = undetermined + (NEW.outcome = 'undetermined') - (OLD.outcome = 'undetermined')
  FROM study_cases sc
  WHERE sc.case_id = OLD.case_id AND grid_point_summaries.study_id = sc.study_id
    AND grid_point_summaries.grid_key = sc.grid_key;
  UPDATE study_summaries SET result_set_version = result_set_version + 1
  WHERE study_id IN (SELECT study_id FROM study_cases WHERE case_id IN (OLD.case_id, NEW.case_id));
END;
CREATE TRIGGER summaries_after_result_delete AFTER DELETE ON results
BEGIN
  UPDATE grid_point_summaries SET
    stick = stick - (OLD.outcome = 'stick'),
    bounce = bounce - (OLD.outcome = 'bounce'),
    break_up = break_up - (OLD.outcome = 'break-up'),
    undetermined = undetermined - (OLD.outcome = 'undetermined')
  FROM study_cases sc
  WHERE sc.case_id = OLD.case_id AND grid_point_summaries.study_id = sc.study_id
    AND grid_point_summaries.grid_key = sc.grid_key;
  UPDATE study_summaries SET result_set_version = result_set_version + 1
  WHERE study_id IN (SELECT study_id FROM study_cases WHERE case_id = OLD.case_id);
END;
)sql";

constexpr std::string_view kDropTriggers = R"sql(
DROP TRIGGER IF EXISTS summaries_after_study_insert;
DROP TRIGGER IF EXISTS summaries_after_link;
DROP TRIGGER IF EXISTS summaries_after_case_change;
DROP TRIGGER IF EXISTS summaries_after_result_insert;
DROP TRIGGER IF EXISTS summaries_after_result_update;
DROP TRIGGER IF EXISTS summaries_after_result_delete;
)sql";

// The summaries as the triggers keep them, computed from scratch; versions are kept and raised.
constexpr std::string_view kRecompute = R"sql(
INSERT OR IGNORE INTO study_summaries (study_id) SELECT id FROM studies;
UPDATE study_summaries SET
  (queued, running, done, failed, cancelled, first_started_at, last_finished_at, finished_here) = (
    SELECT count(*) FILTER (WHERE c.status = 'queued'), count(*) FILTER (WHERE c.status = 'running'),
           count(*) FILTER (WHERE c.status = 'done'), count(*) FILTER (WHERE c.status = 'failed'),
           count(*) FILTER (WHERE c.status = 'cancelled'), min(c.started_at), max(c.finished_at),
           count(*) FILTER (WHERE c.status IN ('done', 'failed') AND c.finished_at >= s.created_at)
    FROM study_cases sc JOIN cases c ON c.id = sc.case_id JOIN studies s ON s.id = sc.study_id
    WHERE sc.study_id = study_summaries.study_id),
  case_state_version = case_state_version + 1,
  result_set_version = result_set_version + 1;
DELETE FROM grid_point_summaries;
INSERT INTO grid_point_summaries
  (study_id, grid_key, position, grid_point, cases, stick, bounce, break_up, undetermined, failed)
SELECT sc.study_id, sc.grid_key, min(sc.position), min(sc.grid_point), count(*),
       count(*) FILTER (WHERE r.outcome = 'stick'), count(*) FILTER (WHERE r.outcome = 'bounce'),
       count(*) FILTER (WHERE r.outcome = 'break-up'), count(*) FILTER (WHERE r.outcome = 'undetermined'),
       count(*) FILTER (WHERE c.status = 'failed')
FROM study_cases sc JOIN cases c ON c.id = sc.case_id LEFT JOIN results r ON r.case_id = sc.case_id
GROUP BY sc.study_id, sc.grid_key;
)sql";

}  // namespace

void drop_store_summary_triggers(SqliteDatabase& db) { db.execute(kDropTriggers); }

void rebuild_store_summaries(SqliteDatabase& db) {
  drop_store_summary_triggers(db);
  db.execute(kRecompute);
  db.execute(kStudyTrigger);
  db.execute(kLinkTrigger);
  db.execute(kCaseTrigger);
  db.execute(kResultTriggers);
}

bool has_store_summaries(SqliteDatabase& db) {
  auto statement = db.prepare(
      "SELECT count(*) FROM sqlite_schema WHERE type = 'table' AND name IN ('study_summaries', "
      "'grid_point_summaries')");
  statement.step();
  return statement.integer(0) == 2;
}

}  // namespace aerobreak
