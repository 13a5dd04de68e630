#pragma once
#include "orchestrator/service/endpoints.hpp"

namespace aerobreak::endpoint {

// GET (and HEAD) /api/studies/ID/tables?format=...&kind=...: the study's lookup tables for
// system codes (docs/EXPORT.md), computed on the store's reader connections (an export never
// waits for, nor holds up, the scheduler), once per result-set version and request
// (Endpoints::tables), sent gzip-compressed to a client that accepts it, with an ETag.
void get_study_table(Endpoints&, const httplib::Request&, httplib::Response&);

}  // namespace aerobreak::endpoint
