#pragma once
#include <httplib.h>

#include "orchestrator/store/store.hpp"

namespace aerobreak {

// GET (and HEAD) /api/studies/ID/tables?format=...&kind=...: the study's lookup tables for
// system codes (docs/EXPORT.md), computed on the store's reader connections: an export never
// waits for, nor holds up, the scheduler.
void register_table_endpoints(httplib::Server& server, Store& store);

}  // namespace aerobreak
