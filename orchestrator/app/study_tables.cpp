#include "orchestrator/service/study_tables.hpp"

#include "orchestrator/fitting/correlation_set.hpp"
#include "orchestrator/service/correlation_cache.hpp"

namespace aerobreak {

namespace {

CorrelationSet fits_of(Store& store, const StudyRecord& study) {
  try {
    return study_correlations(store, study, correlation_request(study, std::nullopt));
  } catch (const CorrelationRequestError& error) {
    throw ExportError(409, "study", error.what());
  }
}

}  // namespace

LookupTable export_lookup_table(Store& store, const StudyRecord& study, const ExportRequest& request) {
  if (request.kind != TableKind::fit) return study_lookup_table(store, study.id, request);
  const auto fits = fits_of(store, study);
  return study_lookup_table(store, study.id, request, &fits);
}

RenderedTable export_file(Store& store, const StudyRecord& study, const ExportRequest& request) {
  if (request.kind == TableKind::correlations) return correlation_code_file(store, study.id, request, fits_of(store, study));
  return render_table(export_lookup_table(store, study, request), request, study.id);
}

}  // namespace aerobreak
