#include "orchestrator/fitting/estimate_json.hpp"

#include <cmath>

namespace aerobreak {

nlohmann::ordered_json number_or_null(const std::optional<double>& value) {
  return value && std::isfinite(*value) ? nlohmann::ordered_json(*value) : nlohmann::ordered_json(nullptr);
}

nlohmann::ordered_json mean_json(const std::optional<MeanEstimate>& estimate) {
  if (!estimate)
    return {
        {"n", 0}, {"mean", nullptr}, {"standard_deviation", nullptr}, {"standard_error", nullptr}, {"ci95", nullptr}};
  return {{"n", estimate->count},
          {"mean", number_or_null(estimate->mean)},
          {"standard_deviation", number_or_null(estimate->standard_deviation)},
          {"standard_error", number_or_null(estimate->standard_error)},
          {"ci95", estimate->lower && estimate->upper ? nlohmann::ordered_json::array({number_or_null(estimate->lower),
                                                                                       number_or_null(estimate->upper)})
                                                      : nlohmann::ordered_json(nullptr)}};
}

nlohmann::ordered_json proportion_json(std::size_t count, const std::optional<ProportionEstimate>& estimate) {
  return {{"count", count},
          {"probability", estimate ? nlohmann::ordered_json(estimate->probability) : nullptr},
          {"ci95", estimate ? nlohmann::ordered_json::array({estimate->lower, estimate->upper})
                            : nlohmann::ordered_json(nullptr)}};
}

}  // namespace aerobreak
