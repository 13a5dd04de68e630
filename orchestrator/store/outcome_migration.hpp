#pragma once
#include "orchestrator/store/sqlite_database.hpp"

namespace aerobreak {

// Store migration 2, the part SQL cannot do: every stored result is classified again by what
// leaves the wall (engine/impact/outcome.hpp) from its stored fragments (the fragments table,
// with the window-mean velocities of its document's /fragments/list), without re-running it. Its
// columns and its document's /outcome are rewritten (/outcome/reclassified_from keeps the former
// class); what the former results did not record (damage ratio, small-strain check, energy
// groups) stays null.
void reclassify_stored_results(SqliteDatabase& db);

}  // namespace aerobreak
