#pragma once
#include <httplib.h>

#include <memory>

#include "orchestrator/app/study_fits.hpp"
#include "orchestrator/store/store.hpp"

namespace aerobreak {

// GET /api/studies/ID/correlations (the summary of every fit) and
// GET /api/studies/ID/correlations/NAME (one fit with its data and curve), both with an optional
// ?covariates=a,b choosing the pooled models' covariates (schemas/openapi.json), served from the
// study's stored fits (`fits`, shared with the table endpoint).
void register_correlation_endpoints(httplib::Server& server, Store& store, std::shared_ptr<StudyFits> fits);

}  // namespace aerobreak
