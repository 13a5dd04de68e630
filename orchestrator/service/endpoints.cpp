#include "orchestrator/service/endpoints.hpp"

#include "orchestrator/service/dashboard_endpoints.hpp"
#include "orchestrator/service/summary_endpoints.hpp"
#include "orchestrator/service/web_endpoints.hpp"

namespace aerobreak {

Endpoints::Endpoints(Store& store_, Scheduler* scheduler_, const ServiceOptions& options_)
    : store(store_),
      scheduler(scheduler_),
      options(options_),
      correlations(store_),
      tables(store_, correlations),
      grids([&store_](std::int64_t study) { return grid_document(store_, study); }),
      outcome_tables([&store_](std::int64_t study) { return outcome_table_document(store_, study); }),
      web_assets(load_web_assets(options_.web_directory)) {}

}  // namespace aerobreak
