#pragma once
#include <Eigen/Dense>

#include "orchestrator/fitting/correlation_set.hpp"

// What a logistic fit of docs/CORRELATIONS.md says at one point (a dose and the values of its
// covariates): the probability with its 95 % band, where the value comes from, and whether the point
// lies in the fit's validity box. One definition for every consumer: the lookup-table export's fit
// table and the generated code of the fitted correlations.
namespace aerobreak {

// Where a predicted probability comes from (the fit table's p_OUTCOME_status column).
enum class PredictionSource {
  maximum_likelihood = 0,  // the fitted curve, Wald band on the logit
  firth = 1,               // the fitted curve under separation (Firth's penalised estimate)
  no_transition = 2,       // the outcome never (or always) occurs in the fit's data: the observed 0 (or 1)
  none = 3,                // no value: too few data, not converged, or a pooled fit under separation
};

struct Prediction {
  BandPoint band;  // NaN when source is none
  PredictionSource source = PredictionSource::none;
  bool inside = false;  // the dose and every covariate inside the fit's validity box
};

// Covariate values in the fit's order (its `covariates`, untransformed). A fit under separation that
// pools along covariates gives none: Firth's estimate is finite but its Wald band is unreliable
// (Heinze & Schemper, Statist. Med. 21 (2002) 2409), and carrying it to other covariate values would
// hide that. A no-transition fit gives the observed 0 or 1 with the Wilson interval of all its cases
// (Wilson, J. Am. Stat. Assoc. 22 (1927) 209) as band: a statement about its validity box only, where
// `inside` says whether the point lies (outside, the transition may lie anywhere).
Prediction predict(const LogisticFit& fit, double dose, const Eigen::VectorXd& covariates = {});

// Whether the point lies in the fit's validity box (ranges widened by 1e-12 relative for rounding).
bool inside_validity(const LogisticFit& fit, double dose, const Eigen::VectorXd& covariates = {});

}  // namespace aerobreak
