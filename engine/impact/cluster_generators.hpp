#pragma once
#include <cstddef>
#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "engine/cluster/cluster.hpp"

namespace aerobreak {

// The one registry of cluster generators (docs/IMPACT.md, "Cluster generators"), shared by impact
// cases (/cluster/generator), studies (their generator, fractal_dimension and prefactor axes) and
// `aerobreak cluster generate`: the same names, parameters, rules and clusters everywhere.

// What a generator is asked for. Fields are named as in a case's /cluster/generator object.
struct GeneratorRequest {
  std::string method = "ballistic";  // a registered name (after find_cluster_generator)
  std::size_t primaries = 1;
  std::uint64_t seed = 0;
  double geometric_mean_diameter = 1.0;  // d; a case's primaries are the unit (1)
  double geometric_standard_deviation = 1.0;
  double fractal_dimension = std::numeric_limits<double>::quiet_NaN();  // tunable
  double prefactor = std::numeric_limits<double>::quiet_NaN();          // tunable
  bool sintering = true;                                                // dlca
};

// A field of a request that breaks a generator's rules, and why ("applies to tunable only").
struct GeneratorViolation {
  std::string field;  // e.g. "fractal_dimension"
  std::string message;
};

struct ClusterGenerator {
  std::string_view name;
  std::vector<std::string_view> aliases;   // older spellings, accepted and stored as `name`
  std::string_view summary;                // one line: what it builds, after whom
  std::vector<std::string_view> fields;    // the fields it takes beyond method, primaries, seed
  std::vector<std::string_view> required;  // those of `fields` a request must give
  Cluster (*build)(const GeneratorRequest& request);
};

// Every generator, in the order the documentation lists them.
const std::vector<ClusterGenerator>& cluster_generators();

// The generator of a name or alias; nullptr if there is none.
const ClusterGenerator* find_cluster_generator(std::string_view name);

// "ballistic (alias bcca), dlca, tunable": for help texts and error messages.
std::string cluster_generator_names();

// The fields a request of `method` may set: the common ones (method, primaries, seed,
// geometric_mean_diameter where the caller offers it, geometric_standard_deviation) and the
// generator's own. False for an unknown method.
bool generator_takes(std::string_view method, std::string_view field);

// The rules the request breaks, each naming its field: an unknown method, a count below 1, a
// diameter or spread out of range, Df or kf out of range, or, for dlca, a spread other than 1.
// `given` lists the generator-specific fields the caller set: one its method does not take is a
// violation, and so is a required one that is missing.
std::vector<GeneratorViolation> check_generator_request(const GeneratorRequest& request,
                                                        const std::vector<std::string>& given);

// A case's /cluster/generator object (schema-valid) read into a request, with the generator's
// rules checked; aliases are resolved. Violations name their field.
GeneratorRequest read_generator_request(const nlohmann::ordered_json& generator,
                                        std::vector<GeneratorViolation>& violations);

// The request as a completed /cluster/generator object: the registered method name, the common
// fields and the generator's own fields (with their defaults), nothing else. A case stores this,
// so that an alias and the name give the same document (and content hash).
nlohmann::ordered_json generator_document(const GeneratorRequest& request);

// Builds the cluster (throws what the generator throws for a request it cannot build).
Cluster generate_cluster(const GeneratorRequest& request);

}  // namespace aerobreak
