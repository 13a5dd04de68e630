#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>

#include "engine/dem/relaxation.hpp"
#include "engine/impact/cluster_generators.hpp"
#include "engine/io/cluster_library.hpp"

namespace aerobreak {

// A run of generated clusters for a library or an XYZ file (`aerobreak cluster generate`): the
// registry's request (its seed is derived per cluster), relaxed or not, in reduced units with the
// material of gamma/k_n and Poisson ratio nu (cluster_relaxation.hpp).
struct ClusterGeneration {
  GeneratorRequest request;  // request.seed is the base seed
  bool relax = true;
  double gamma_over_kn = 0.001;
  double poisson_ratio = 0.3;
};

// One generated cluster with what the library records of it.
struct GeneratedCluster {
  Cluster cluster;
  std::uint64_t seed = 0;                      // derived_seed(base seed, index)
  std::optional<RelaxationResult> relaxation;  // none when not relaxed
  ClusterOrigin origin;                        // the request, the seed derivation, the relaxation
};

// Cluster `index` of a generation: generated from its derived seed (seed_derivation.hpp), relaxed
// when asked. Throws std::runtime_error naming the cluster (`name`) and its seed when the
// relaxation leaves it unfit for an impact (relaxation_defect).
GeneratedCluster generate_library_cluster(const ClusterGeneration& generation, std::size_t index,
                                          const std::string& name);

}  // namespace aerobreak
