#pragma once
#include "orchestrator/export/lookup_tables.hpp"
#include "orchestrator/export/table_formats.hpp"
#include "orchestrator/store/store.hpp"

namespace aerobreak {

// The lookup table an export asks for (docs/EXPORT.md), from the store's reader connections: kind
// grid and sections from the stored results, kind fit from the study's correlations fitted now
// (study_correlations, which reads and never writes). What GET /api/studies/ID/tables and
// `aerobreak export` both serve. ExportError on a request the study cannot serve.
LookupTable export_lookup_table(Store& store, const StudyRecord& study, const ExportRequest& request);

// The file an export asks for: a lookup table rendered in its format, or for kind=correlations the
// fitted correlations as code (Fortran, C) or JSON. ExportError on a request the study cannot serve.
RenderedTable export_file(Store& store, const StudyRecord& study, const ExportRequest& request);

}  // namespace aerobreak
