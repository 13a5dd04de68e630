#pragma once
#include "orchestrator/store/sqlite_database.hpp"

namespace aerobreak {

// Store migration 9, the part SQL cannot do: every stored case's N (cases.primaries) read from its
// document as the engine reads it (engine/impact/case_inputs.hpp); null for a cluster file, whose
// N the document does not say.
void fill_case_primaries(SqliteDatabase& db);

}  // namespace aerobreak
