#pragma once
#include "orchestrator/store/sqlite_database.hpp"

namespace aerobreak {

// Per-study summaries that the read endpoints serve in O(1) and O(grid points) instead of
// aggregating every case per request (docs/ORCHESTRATOR.md, "Store"):
//   study_summaries       one row per study: cases by status, first start, last finish, cases
//                         finished since the study was created, and two versions
//                         (case_state_version: +1 whenever one of its cases changes status or
//                         times; result_set_version: +1 whenever a result of one of its cases is
//                         stored, changed or removed);
//   grid_point_summaries  one row per grid point of a study: cases, outcome counts, failures.
// SQLite triggers keep them up to date in the transaction of every change to studies, cases,
// study_cases and results, whoever makes it (the store's writer, a migration's SQL, a by-hand fix).
//
// rebuild_store_summaries recomputes both tables from those tables and (re)creates the triggers;
// versions only grow (a rebuild adds 1). migrate_store removes the triggers before every migration
// step (so that a step may re-create any table: SQLite refuses to rename a table into place while
// a trigger names a table that is gone) and rebuilds after it once the tables exist, so that a step
// which rewrites results (e.g. re-classifies outcomes) or links leaves the summaries right. A change
// of the triggers' SQL must come with a migration step (possibly empty) for stores to pick it up.
void rebuild_store_summaries(SqliteDatabase& db);
void drop_store_summary_triggers(SqliteDatabase& db);

// Whether the database has the summary tables (migration 2 made them).
bool has_store_summaries(SqliteDatabase& db);

}  // namespace aerobreak
