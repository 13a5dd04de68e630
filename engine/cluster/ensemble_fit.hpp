#pragma once
#include <optional>
#include <span>
#include <string>

#include "engine/cluster/cluster.hpp"
#include "engine/cluster/cluster_analysis.hpp"
#include "engine/cluster/fractal_scaling_fit.hpp"

namespace aerobreak {

// The fit N = k_f (Rg/a)^D_f over an ensemble of clusters (report figure 2b), a the mean primary
// radius over all their primaries: attempted when the clusters have at least two sizes; holds the
// fit, or why it could not be made.
struct EnsembleFractalFit {
  bool attempted = false;
  std::optional<FractalScalingFit> fit;
  double primary_radius = 0.0;
  std::string failure;
};

// `analyses[i]` is analyse_cluster(clusters[i]).
EnsembleFractalFit fit_cluster_ensemble(std::span<const Cluster> clusters, std::span<const ClusterAnalysis> analyses);

}  // namespace aerobreak
