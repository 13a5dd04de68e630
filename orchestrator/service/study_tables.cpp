#include "orchestrator/service/study_tables.hpp"

#include "orchestrator/fitting/correlation_set.hpp"
#include "orchestrator/service/correlation_cache.hpp"

namespace aerobreak {

LookupTable export_lookup_table(Store& store, const StudyRecord& study, const ExportRequest& request) {
  if (request.kind != TableKind::fit) return study_lookup_table(store, study.id, request);
  try {
    const auto fits = study_correlations(store, study, correlation_request(study, std::nullopt));
    return study_lookup_table(store, study.id, request, &fits);
  } catch (const CorrelationRequestError& error) {
    throw ExportError(409, "study", error.what());
  }
}

}  // namespace aerobreak
