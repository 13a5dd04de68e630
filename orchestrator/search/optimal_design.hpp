#pragma once
#include <cstdint>
#include <vector>

#include "orchestrator/search/response_fit.hpp"

namespace aerobreak {

// A crossing still wanted: its response's fit (with a finite estimate), its level and the
// half-width wanted in dose units.
struct DesignTarget {
  const ResponseFit* fit = nullptr;
  double level = 0.5;
  double half_width = 1.0;
};

// Phase II of the search: `count` doses picked one at a time from `candidates` (doses). The
// first, third, ... pick is the dose that most lowers sum over targets of
// E[Var(theta_t)] / half_width_t^2 given the results and the doses picked before it (the
// crossings' own precision); the second, fourth, ... the one that most raises
// E[log det M] over the fits (D-optimality: the slope's precision, as in Neyer's D-optimal
// sensitivity test, Technometrics 36 (1994) 61, and the second phase of Wu & Tian's three-phase
// design, J. Statist. Plann. Inference 149 (2014) 1). A design that only aims at the crossing
// piles its cases onto the current estimate, learns little of the slope, and ends groups on
// lucky narrow intervals whose coverage is poor (docs/ADAPTIVE.md, "Validation").
// Var(theta) = g' M^-1 g is the asymptotic variance of the crossing theta = (logit(level) - b0) / b1 (gradient g = -(1,
// theta) / b1), M the Fisher information of (b0, b1), sum over cases of p (1 - p) (1, x)(1, x)'. The expectation is
// over `draws` draws of (b0, b1) from each fit's normal approximation N(b-hat, I^-1) (Chaloner & Larntz, J. Statist.
// Plann. Inference 21 (1989) 191: Bayesian optimal design for logistic regression, which unlike
// a plug-in locally optimal design does not stake every case on the current estimate), seeded by
// `seed`. Every pick adds its information to every fit: one case informs all responses.
// `determined` (one per candidate) is the chance q that a case there ends determined
// (determined_chance.hpp): an undetermined case is left out of the fits, so both criteria are the
// expectation over the two, q U(M + I_x) + (1 - q) U(M), and a pick adds q I_x to the information
// the later picks of the round see. Where q = 1 the picks are those of the plain criteria.
std::vector<std::size_t> optimal_doses(const std::vector<DesignTarget>& targets, const std::vector<double>& candidates,
                                       const std::vector<double>& determined, std::size_t count, std::uint64_t seed,
                                       int draws = 100);

// E[Var(theta)] of a crossing under the results alone, over the same draws: the precision the
// results give once the uncertainty of the slope is counted, which a lucky narrow profile
// interval from few cases does not show.
double expected_crossing_variance(const DesignTarget& target, std::uint64_t seed, int draws = 100);

// splitmix64 (Steele, Lea & Flood 2014): the deterministic generator of the search's draws.
std::uint64_t splitmix64(std::uint64_t& state);

}  // namespace aerobreak
