#pragma once
#include <optional>
#include <string>

#include "engine/cluster/cluster.hpp"
#include "engine/dem/relaxation.hpp"

namespace aerobreak {

// A cluster relaxed (relax_cluster) in reduced units, with the material of gamma/k_n and Poisson
// ratio nu and the default contact model, of which relax_cluster uses the normal law only: JKR
// with displacement-controlled separation.
RelaxationResult relax_reduced_cluster(const Cluster& cluster, double gamma_over_kn, double poisson_ratio);

// Why a relaxed cluster is not fit for an impact (docs/MODEL.md 11.1: it must be at mechanical
// equilibrium and intact): the relaxation did not converge, or it broke contacts (the cluster
// came apart). Empty when it is fit.
std::optional<std::string> relaxation_defect(const RelaxationResult& relaxation);

}  // namespace aerobreak
