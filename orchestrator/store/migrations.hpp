#pragma once
#include <span>
#include <string_view>

#include "orchestrator/store/sqlite_database.hpp"

namespace aerobreak {

// One step of the store's schema: applying `sql`, then `upgrade` (what SQL alone cannot do; null
// for none), to a database at version - 1 brings it to `version`. Steps are never edited once
// released; a change is a new step.
struct Migration {
  int version;
  std::string_view summary;
  std::string_view sql;
  void (*upgrade)(SqliteDatabase& db) = nullptr;
};

std::span<const Migration> store_migrations();
int latest_store_version();

// Brings the database to the latest version, each step in its own transaction together with
// PRAGMA user_version (and, once they exist, a rebuild of the summaries: store_summaries.hpp), so
// that a crash leaves the file at a whole version. A file written by a
// newer aerobreak (user_version above latest) is refused rather than misread. Returns the version
// the file had before.
int migrate_store(SqliteDatabase& db);
// The same with the steps given (tests: a later step that rewrites results).
int migrate_store(SqliteDatabase& db, std::span<const Migration> steps);

}  // namespace aerobreak
