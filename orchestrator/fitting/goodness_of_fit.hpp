#pragma once
#include <vector>

#include "orchestrator/fitting/binomial_glm.hpp"
#include "orchestrator/fitting/correlation_set.hpp"

namespace aerobreak {

// P(X > x) for X ~ chi^2 with `df` degrees of freedom (regularised upper incomplete gamma,
// Boost.Math); nullopt for df <= 0.
std::optional<double> chi_square_upper_tail(double x, double df);

// The goodness of fit of a binomial model with `parameters` coefficients. Grouped data (a row with
// more than one trial): the deviance and Pearson's X^2 against chi^2 with rows - parameters degrees
// of freedom (McCullagh & Nelder, sec. 4.4.3). Ungrouped data (one trial a row), where neither has
// a chi^2 law: the Hosmer-Lemeshow statistic over ten groups of fitted probability, against chi^2
// with 8 degrees of freedom (Hosmer & Lemeshow, Applied Logistic Regression, 2nd ed., sec. 5.2.2).
std::vector<GoodnessOfFit> binomial_goodness_of_fit(const BinomialData& data, const GlmFit& fit,
                                                    std::size_t parameters);

}  // namespace aerobreak
