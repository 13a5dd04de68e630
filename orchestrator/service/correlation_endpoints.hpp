#pragma once
#include <httplib.h>

#include "orchestrator/store/store.hpp"

namespace aerobreak {

// GET /api/studies/ID/correlations (the summary of every fit) and
// GET /api/studies/ID/correlations/NAME (one fit with its data and curve), both with an optional
// ?covariates=a,b choosing the pooled models' covariates (schemas/openapi.json). The endpoints own
// the cache of fits they serve from.
void register_correlation_endpoints(httplib::Server& server, Store& store);

}  // namespace aerobreak
