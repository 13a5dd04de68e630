#pragma once
#include <httplib.h>

#include <memory>

#include "orchestrator/app/study_fits.hpp"
#include "orchestrator/app/study_tables.hpp"
#include "orchestrator/service/grid_point_cache.hpp"
#include "orchestrator/service/service.hpp"
#include "orchestrator/service/versioned_documents.hpp"
#include "orchestrator/service/web_assets.hpp"
#include "orchestrator/store/data_file_check.hpp"

namespace aerobreak {

// What the endpoints of one service share: the store, the scheduler a submission wakes (null for
// a read-only service), the service's options, and what is kept between requests. It lives as
// long as the HTTP server that answers with it.
struct Endpoints {
  Endpoints(Store& store, Scheduler* scheduler, const ServiceOptions& options);

  Store& store;
  Scheduler* scheduler;
  const ServiceOptions& options;
  DataFileChecker data_files;                   // a case's HDF5 file against the size and SHA-256 recorded
  GridPointCache grid_points;                   // a study's grid points, for the axis filters
  StudyFits correlations;                       // fitted once per result set, stored (docs/CORRELATIONS.md)
  StudyTables tables;                           // lookup tables built once per result-set version and request
  VersionedDocuments grids;                     // GET .../grid, serialised per study version
  VersionedDocuments outcome_tables;            // GET .../outcomes, likewise
  std::shared_ptr<const WebAssets> web_assets;  // the dashboard's files; null: the API only
};

// One endpoint: answers `request` (RequestError for a 4xx; guarded() turns it into its answer).
using EndpointHandler = void (*)(Endpoints&, const httplib::Request&, httplib::Response&);

}  // namespace aerobreak
