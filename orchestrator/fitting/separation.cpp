#include "orchestrator/fitting/separation.hpp"

#include <optional>

namespace aerobreak {

std::optional<Separation> find_separation(const BinomialData& data, const GlmFit& maximum_likelihood) {
  if (maximum_likelihood.converged || maximum_likelihood.last_step.norm() == 0.0) return std::nullopt;
  // The step is in the free parameters; without a constraint they are beta itself.
  const Eigen::VectorXd direction = maximum_likelihood.last_step.normalized();
  const Eigen::VectorXd projection = data.design * direction;
  const double scale = projection.cwiseAbs().maxCoeff();
  if (!(scale > 0.0)) return std::nullopt;
  const double on_plane = 1e-6 * scale;
  Separation separation;
  separation.direction = direction;
  for (Eigen::Index i = 0; i < projection.size(); ++i) {
    const bool has_successes = data.successes[i] > 0.0;
    const bool has_failures = data.successes[i] < data.trials[i];
    if (std::abs(projection[i]) <= on_plane) continue;
    if ((has_successes && projection[i] < 0.0) || (has_failures && projection[i] > 0.0)) return std::nullopt;
    separation.perfectly_predicted.push_back(static_cast<std::size_t>(i));
  }
  separation.complete = separation.perfectly_predicted.size() == static_cast<std::size_t>(projection.size());
  return separation;
}

}  // namespace aerobreak
