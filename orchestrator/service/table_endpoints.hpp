#pragma once
#include <httplib.h>

#include <memory>

#include "orchestrator/app/study_tables.hpp"
#include "orchestrator/store/store.hpp"

namespace aerobreak {

// GET (and HEAD) /api/studies/ID/tables?format=...&kind=...: the study's lookup tables for
// system codes (docs/EXPORT.md), computed on the store's reader connections (an export never
// waits for, nor holds up, the scheduler), once per result-set version and request (`tables`),
// sent gzip-compressed to a client that accepts it, with an ETag.
void register_table_endpoints(httplib::Server& server, Store& store, std::shared_ptr<StudyTables> tables);

}  // namespace aerobreak
