#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

// What a set of correlations is asked for and where it comes from (no Eigen here: the service's
// headers include this next to httplib).
namespace aerobreak {

// A covariate of the pooled models: a numeric axis of the study, entered as log(value) or value.
struct Covariate {
  std::string axis;
  bool logarithmic = true;
};

// Every member is part of what is fitted: request_key (the store's key of a set) covers them all.
struct CorrelationRequest {
  std::string speed_axis;  // the axis that sets the impact speed; empty: not swept
  // The axes the pooled models (and the scaling laws) model, as covariates: they pool along these
  // only, one fit per condition of the other axes (none: no pooled model, no scaling law).
  std::vector<Covariate> covariates;
  std::array<double, 3> levels{0.1, 0.5, 0.9};
  // The axis of the cluster size N (empty when the study has none): the covariate the lookup-table
  // export evaluates at sizes the study did not run.
  std::string size_axis;
};

struct Provenance {
  std::int64_t study = 0;
  std::string result_set_hash;
  std::int64_t result_set_version = 0;
  std::string aerobreak_version;
};

}  // namespace aerobreak
