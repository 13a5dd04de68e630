#include "engine/dem/cluster_relaxation.hpp"

#include <array>
#include <cmath>
#include <cstdio>

#include "engine/core/units.hpp"
#include "engine/dem/impact_placement.hpp"

namespace aerobreak {

RelaxationResult relax_reduced_cluster(const Cluster& cluster, double gamma_over_kn, double poisson_ratio) {
  const Material material = reduced_material(gamma_over_kn, poisson_ratio);
  return relax_cluster(particles_from_cluster(cluster, material.density), {material}, ContactModelSpec{});
}

std::optional<std::string> relaxation_defect(const RelaxationResult& relaxation) {
  if (!relaxation.converged) {
    std::array<char, 32> force{'n', '/', 'a'};
    if (std::isfinite(relaxation.largest_force))
      std::snprintf(force.data(), force.size(), "%.4g", relaxation.largest_force);
    return "relaxation did not converge in " + std::to_string(relaxation.steps) + " steps (largest net force " +
           force.data() + " times the primary's own F_c)";
  }
  if (relaxation.contacts_broken > 0)
    return "relaxation broke " + std::to_string(relaxation.contacts_broken) + " contacts (the cluster came apart)";
  return std::nullopt;
}

}  // namespace aerobreak
