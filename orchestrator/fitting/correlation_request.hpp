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

struct CorrelationRequest {
  std::string speed_axis;             // the axis that sets the impact speed; empty: not swept
  std::vector<Covariate> covariates;  // of the pooled models (none: groups pooled as they are)
  std::array<double, 3> levels{0.1, 0.5, 0.9};
  // The axis of the cluster size N. When set, the logistic models in impact speed are also fitted
  // pooled over the sizes, one per group of the other axes (CorrelationSet::size_pooled, which the
  // lookup-table export evaluates at sizes the study did not run); empty: not fitted.
  std::string size_axis;
};

struct Provenance {
  std::int64_t study = 0;
  std::string result_set_hash;
  std::int64_t result_set_version = 0;
  std::string aerobreak_version;
};

}  // namespace aerobreak
