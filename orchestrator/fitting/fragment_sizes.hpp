#pragma once
#include <cstdint>
#include <utility>
#include <vector>

#include "orchestrator/fitting/correlation_set.hpp"

namespace aerobreak {

// The re-entrained fragment sizes of one grid point (all its cases pooled) against two laws on
// s = 1..N, both fitted by maximum likelihood (Clauset, Shalizi & Newman, SIAM Rev. 51 (2009) 661):
// - a discrete power law P(s) = s^-tau / sum_{t=1..N} t^-tau (upper end N: no fragment exceeds the
//   cluster), tau by Newton, its standard error from the observed information;
// - a discretised lognormal P(s) = [Phi((ln(s+1/2) - mu)/sigma) - Phi((ln(s-1/2) - mu)/sigma)] / Z,
//   Z the same over 1..N, (mu, sigma) by Newton on numerical derivatives.
// Goodness of fit: each law's Kolmogorov-Smirnov distance max_s |F_data(s) - F_law(s)|, and
// Vuong's test of the two (Vuong, Econometrica 57 (1989) 307): V = sum l_i / (sqrt(n) sd(l_i)),
// l_i = ln P_lognormal(s_i) - ln P_power(s_i); V > 0 favours the lognormal, p two-sided normal.
// Insufficient data: fewer than 5 fragments or fewer than 2 distinct sizes.
FragmentSizeFit fit_fragment_sizes(const std::vector<std::int64_t>& sizes, std::int64_t largest_size);

// One fit per grid point that has re-entrained fragments.
std::vector<FragmentSizeFit> fit_fragment_distributions(const CaseOutcomeTable& table);

}  // namespace aerobreak
