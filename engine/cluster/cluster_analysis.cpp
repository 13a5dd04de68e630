#include "engine/cluster/cluster_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>

#include "engine/cluster/cluster_contacts.hpp"
#include "engine/cluster/line_fit.hpp"

namespace aerobreak {
namespace {

void require_primaries(const Cluster& cluster, const char* what) {
  if (cluster.size() == 0) throw std::invalid_argument(std::string(what) + ": cluster is empty");
}

double mass(double radius) { return radius * radius * radius; }

double mean_radius(const Cluster& cluster) {
  return std::accumulate(cluster.radius.begin(), cluster.radius.end(), 0.0) / static_cast<double>(cluster.size());
}

}  // namespace

Vec3 centre_of_mass(const Cluster& cluster) {
  require_primaries(cluster, "centre_of_mass");
  Vec3 weighted;
  double total = 0.0;
  for (std::size_t i = 0; i < cluster.size(); ++i) {
    const double m = mass(cluster.radius[i]);
    weighted += m * cluster.position[i];
    total += m;
  }
  return weighted / total;
}

double radius_of_gyration(const Cluster& cluster) {
  const Vec3 com = centre_of_mass(cluster);
  double weighted = 0.0;
  double total = 0.0;
  for (std::size_t i = 0; i < cluster.size(); ++i) {
    const double m = mass(cluster.radius[i]);
    weighted += m * norm2(cluster.position[i] - com);
    total += m;
  }
  return std::sqrt(weighted / total);
}

double maximum_extent(const Cluster& cluster) {
  const Vec3 com = centre_of_mass(cluster);
  std::vector<std::pair<double, std::size_t>> reach;  // (rho_i, i), farthest first
  reach.reserve(cluster.size());
  for (std::size_t i = 0; i < cluster.size(); ++i) {
    reach.emplace_back(norm(cluster.position[i] - com) + cluster.radius[i], i);
  }
  std::sort(reach.begin(), reach.end(), std::greater<>());

  double best = 2.0 * *std::max_element(cluster.radius.begin(), cluster.radius.end());
  for (std::size_t a = 0; a + 1 < reach.size(); ++a) {
    if (reach[a].first + reach[a + 1].first <= best) break;
    const std::size_t i = reach[a].second;
    for (std::size_t b = a + 1; b < reach.size(); ++b) {
      if (reach[a].first + reach[b].first <= best) break;
      const std::size_t j = reach[b].second;
      best = std::max(best, norm(cluster.position[i] - cluster.position[j]) + cluster.radius[i] + cluster.radius[j]);
    }
  }
  return best;
}

double filling_factor(const Cluster& cluster) {
  const double rg = radius_of_gyration(cluster);
  if (rg == 0.0) return std::numeric_limits<double>::quiet_NaN();
  double solid = 0.0;
  for (double r : cluster.radius) solid += mass(r);
  const double sphere = std::sqrt(5.0 / 3.0) * rg;
  return solid / (sphere * sphere * sphere);
}

double mass_radius_dimension(const Cluster& cluster) {
  constexpr std::size_t radius_samples = 16;
  constexpr std::size_t max_centres = 2048;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double r_low = 2.0 * (2.0 * mean_radius(cluster));
  const double r_high = 0.5 * radius_of_gyration(cluster);
  if (r_high < 2.0 * r_low) return nan;

  std::vector<double> radii(radius_samples);
  for (std::size_t k = 0; k < radius_samples; ++k) {
    const double t = static_cast<double>(k) / static_cast<double>(radius_samples - 1);
    radii[k] = r_low * std::pow(r_high / r_low, t);
  }
  radii.back() = r_high;

  // shell_mass[k]: mass at distances in (radii[k-1], radii[k]] from the centres, weighted by the
  // centres' masses; summed cumulatively below into the averaged M(r).
  std::vector<double> shell_mass(radius_samples, 0.0);
  double centre_mass = 0.0;
  const std::size_t stride = (cluster.size() + max_centres - 1) / max_centres;
  for (std::size_t c = 0; c < cluster.size(); c += stride) {
    const double mc = mass(cluster.radius[c]);
    centre_mass += mc;
    for (std::size_t j = 0; j < cluster.size(); ++j) {
      const double distance = norm(cluster.position[j] - cluster.position[c]);
      if (distance > r_high) continue;
      const auto shell = std::lower_bound(radii.begin(), radii.end(), distance) - radii.begin();
      shell_mass[static_cast<std::size_t>(shell)] += mc * mass(cluster.radius[j]);
    }
  }

  std::vector<double> log_r(radius_samples);
  std::vector<double> log_m(radius_samples);
  double cumulative = 0.0;
  for (std::size_t k = 0; k < radius_samples; ++k) {
    cumulative += shell_mass[k];
    log_r[k] = std::log(radii[k]);
    log_m[k] = std::log(cumulative / centre_mass);
  }
  return fit_line(log_r, log_m).slope;
}

ClusterAnalysis analyse_cluster(const Cluster& cluster, double contact_tolerance) {
  require_primaries(cluster, "analyse_cluster");
  ClusterAnalysis a;
  a.primary_count = cluster.size();
  a.centre_of_mass = centre_of_mass(cluster);
  a.radius_of_gyration = radius_of_gyration(cluster);
  a.maximum_extent = maximum_extent(cluster);
  const ContactGraph graph = find_contacts(cluster, contact_tolerance);
  a.contact_count = graph.contacts.size();
  a.deep_overlap_count = graph.deep_overlap_count;
  a.mean_coordination_number = 2.0 * static_cast<double>(a.contact_count) / cluster.size();
  a.component_sizes = connected_component_sizes(cluster.size(), graph.contacts);
  a.filling_factor = filling_factor(cluster);
  a.porosity = 1.0 - a.filling_factor;
  a.mass_radius_dimension = mass_radius_dimension(cluster);
  return a;
}

}  // namespace aerobreak
