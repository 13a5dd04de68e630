#include "engine/impact/cluster_generation.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "engine/cluster/seed_derivation.hpp"
#include "engine/dem/cluster_relaxation.hpp"
#include "engine/dem/impact_placement.hpp"

namespace aerobreak {
namespace {

// What the library records of a generation: the registry's request (as a case would name it),
// the diameter, the seed derivation and the relaxation.
nlohmann::ordered_json generation_parameters(const ClusterGeneration& generation, const GeneratorRequest& request,
                                             std::size_t index, const std::optional<RelaxationResult>& relaxation) {
  nlohmann::ordered_json parameters = generator_document(request);
  parameters.erase("seed");
  parameters["geometric_mean_diameter"] = request.geometric_mean_diameter;
  parameters["base_seed"] = generation.request.seed;
  parameters["index"] = index;
  parameters["seed_derivation"] = "splitmix64 output index+1 from base_seed";
  if (generator_takes(request.method, "fractal_dimension")) parameters["gyration_convention"] = "solid_spheres";
  parameters["relaxation"] = nullptr;
  if (relaxation)
    parameters["relaxation"] = {{"normal_law", "jkr"},
                                {"gamma_over_kn", generation.gamma_over_kn},
                                {"poisson_ratio", generation.poisson_ratio},
                                {"steps", relaxation->steps},
                                {"contacts", relaxation->contacts},
                                {"largest_force_over_pull_off", relaxation->largest_force}};
  return parameters;
}

}  // namespace

GeneratedCluster generate_library_cluster(const ClusterGeneration& generation, std::size_t index,
                                          const std::string& name) {
  GeneratorRequest request = generation.request;
  request.seed = derived_seed(generation.request.seed, index);
  GeneratedCluster out;
  out.seed = request.seed;
  out.cluster = generate_cluster(request);
  if (generation.relax) {
    out.relaxation = relax_reduced_cluster(out.cluster, generation.gamma_over_kn, generation.poisson_ratio);
    if (const auto defect = relaxation_defect(*out.relaxation))
      throw std::runtime_error("cluster " + name + " (seed " + std::to_string(request.seed) + "): " + *defect +
                               "; not stored");
    out.cluster = cluster_from_particles(out.relaxation->particles);
  }
  // k_f where the generator imposes one.
  const double prefactor =
      generator_takes(request.method, "prefactor") ? request.prefactor : std::numeric_limits<double>::quiet_NaN();
  out.origin = {request.method, generation_parameters(generation, request, index, out.relaxation).dump(), request.seed,
                prefactor, generation.relax};
  return out;
}

}  // namespace aerobreak
