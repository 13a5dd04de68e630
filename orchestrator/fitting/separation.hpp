#pragma once
#include <Eigen/Dense>
#include <optional>
#include <vector>

#include "orchestrator/fitting/binomial_glm.hpp"

namespace aerobreak {

// Separation (Albert & Anderson, Biometrika 71 (1984) 1): a direction d with x_i'd >= 0 wherever
// row i has successes and x_i'd <= 0 wherever it has failures, x d != 0. Then the likelihood grows
// without bound along d and no maximum-likelihood estimate exists. Complete: no row lies on the
// plane x'd = 0; quasi-complete: some rows (those with both outcomes among them) do.
struct Separation {
  bool complete = false;
  Eigen::VectorXd direction;                     // unit d
  std::vector<std::size_t> perfectly_predicted;  // rows off the plane: their outcome is certain in the limit
};

// A maximum-likelihood fit that did not converge is checked for separation along its last Newton
// step: in a separated problem the finite part of beta converges while the iterates run off along
// d, so the step turns into d. The direction is accepted only when it passes the definition above
// on every row (the certificate), with rows within 1e-6 of the largest |x_i'd| counted as on the
// plane. nullopt for a fit that converged, or whose divergence is not a separation.
std::optional<Separation> find_separation(const BinomialData& data, const GlmFit& maximum_likelihood);

}  // namespace aerobreak
