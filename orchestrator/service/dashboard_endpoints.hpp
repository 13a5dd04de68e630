#pragma once
#include <cstdint>
#include <string>

#include "orchestrator/service/endpoints.hpp"

namespace aerobreak {

// The grid statistics of a study as GET /api/studies/ID/grid serves them (Endpoints::grids keeps
// them serialised per study version).
std::string grid_document(Store& store, std::int64_t study);

// What the dashboard (web/) asks the server to aggregate, so that a study of 100,000 cases is never
// pulled into the browser (schemas/openapi.json documents each).
namespace endpoint {

// GET /api/progress: the newest studies with their progress.
void list_study_progress(Endpoints&, const httplib::Request&, httplib::Response&);
// GET /api/studies/ID/grid: per-grid-point statistics with the study's axes.
void get_study_grid(Endpoints&, const httplib::Request&, httplib::Response&);
// GET /api/studies/ID/case-table: the cases filtered and paged.
void get_study_case_table(Endpoints&, const httplib::Request&, httplib::Response&);
// GET /api/studies/ID/fragment-sizes: fragments counted per size and grid point.
void get_study_fragment_sizes(Endpoints&, const httplib::Request&, httplib::Response&);
// GET /api/cases/ID/data: a case's HDF5 file, checked against its recorded size and SHA-256.
void get_case_data(Endpoints&, const httplib::Request&, httplib::Response&);

}  // namespace endpoint
}  // namespace aerobreak
