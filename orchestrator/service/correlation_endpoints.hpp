#pragma once
#include "orchestrator/service/endpoints.hpp"

namespace aerobreak::endpoint {

// GET /api/studies/ID/correlations (the summary of every fit) and
// GET /api/studies/ID/correlations/NAME (one fit with its data and curve), both with an optional
// ?covariates=a,b choosing the pooled models' covariates (schemas/openapi.json); served from
// Endpoints::correlations (StudyFits), fitted once per result set and stored.
void get_study_correlations(Endpoints&, const httplib::Request&, httplib::Response&);
void get_study_correlation(Endpoints&, const httplib::Request&, httplib::Response&);

}  // namespace aerobreak::endpoint
