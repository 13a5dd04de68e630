#include "engine/cluster/ensemble_fit.hpp"

#include <set>
#include <stdexcept>
#include <vector>

namespace aerobreak {
namespace {

double mean_primary_radius(std::span<const Cluster> clusters) {
  double sum = 0.0;
  std::size_t count = 0;
  for (const Cluster& each : clusters) {
    for (const double r : each.radius) sum += r;
    count += each.size();
  }
  return sum / static_cast<double>(count);
}

std::size_t distinct_sizes(std::span<const ClusterAnalysis> analyses) {
  std::set<std::size_t> sizes;
  for (const ClusterAnalysis& each : analyses) sizes.insert(each.primary_count);
  return sizes.size();
}

}  // namespace

EnsembleFractalFit fit_cluster_ensemble(std::span<const Cluster> clusters, std::span<const ClusterAnalysis> analyses) {
  EnsembleFractalFit ensemble;
  if (distinct_sizes(analyses) < 2) return ensemble;
  ensemble.attempted = true;
  ensemble.primary_radius = mean_primary_radius(clusters);
  std::vector<SizeRadiusSample> samples;
  for (const ClusterAnalysis& each : analyses)
    samples.push_back({static_cast<double>(each.primary_count), each.radius_of_gyration});
  try {
    ensemble.fit = fit_fractal_scaling(samples, ensemble.primary_radius);
  } catch (const std::invalid_argument& error) {
    ensemble.failure = error.what();
  }
  return ensemble;
}

}  // namespace aerobreak
