#include "engine/impact/cluster_generators.hpp"

#include <algorithm>
#include <cmath>

#include "engine/cluster/ballistic_aggregation.hpp"
#include "engine/cluster/tunable_aggregation.hpp"
#include "engine/growth/diffusion_limited_aggregation.hpp"

namespace aerobreak {
namespace {

using Json = nlohmann::ordered_json;

Cluster build_ballistic(const GeneratorRequest& r) {
  return ballistic_cluster_cluster_aggregation({r.primaries, r.geometric_mean_diameter, r.geometric_standard_deviation},
                                               r.seed);
}

// k_f and D_f in FracVAL's solid-sphere Rg convention (tunable_aggregation.hpp).
Cluster build_tunable(const GeneratorRequest& r) {
  TunableAggregationParameters p;
  p.primary_count = r.primaries;
  p.fractal_dimension = r.fractal_dimension;
  p.prefactor = r.prefactor;
  p.geometric_mean_diameter = r.geometric_mean_diameter;
  p.geometric_standard_deviation = r.geometric_standard_deviation;
  return tunable_cluster_aggregation(p, r.seed);
}

// Grown by the engine at the growth's defaults (gamma/k_n = 0.01, E_b/kT = 100, volume fraction
// 0.1 %; docs/MODEL.md 11.3), whatever the impact's material: a study's gamma/k_n axis then keeps
// the same clusters. Grown in unit diameters and scaled to the requested one (the growth's
// reduced units make its structure independent of the scale).
Cluster build_dlca(const GeneratorRequest& r) {
  DiffusionLimitedParameters p;
  p.primary_count = r.primaries;
  p.sintering = r.sintering;
  Cluster cluster = diffusion_limited_aggregation(p, r.seed);
  for (Vec3& x : cluster.position) x = r.geometric_mean_diameter * x;
  for (double& radius : cluster.radius) radius *= r.geometric_mean_diameter;
  return cluster;
}

const std::vector<std::string_view> kCommonFields{"method", "primaries", "seed", "geometric_mean_diameter",
                                                  "geometric_standard_deviation"};

bool contains(const std::vector<std::string_view>& list, std::string_view item) {
  return std::find(list.begin(), list.end(), item) != list.end();
}

// "the tunable generator" (or "the dlca and tunable generators") for a field some generators take.
std::string generators_taking(std::string_view field) {
  std::vector<std::string> names;
  for (const ClusterGenerator& g : cluster_generators())
    if (contains(g.fields, field)) names.emplace_back(g.name);
  std::string text = "the ";
  for (std::size_t k = 0; k < names.size(); ++k)
    text += (k == 0 ? "" : k + 1 == names.size() ? " and " : ", ") + names[k];
  return text + (names.size() == 1 ? " generator" : " generators");
}

// A field of another generator would be ignored, so it is refused; a required one must be given.
void check_own_fields(const ClusterGenerator& g, const std::vector<std::string>& given,
                      std::vector<GeneratorViolation>& out) {
  for (const std::string& field : given)
    if (!contains(g.fields, field))
      out.push_back({field, "applies to " + generators_taking(field) + " only, not to " + std::string(g.name)});
  for (std::string_view field : g.required)
    if (std::find(given.begin(), given.end(), field) == given.end())
      out.push_back({std::string(field), "is required by the " + std::string(g.name) + " generator"});
}

void check_values(const ClusterGenerator& g, const GeneratorRequest& r, std::vector<GeneratorViolation>& out) {
  if (r.primaries < 1) out.push_back({"primaries", "must be at least 1"});
  if (!(r.geometric_mean_diameter > 0.0) || !std::isfinite(r.geometric_mean_diameter))
    out.push_back({"geometric_mean_diameter", "must be positive"});
  if (!(r.geometric_standard_deviation >= 1.0) || !std::isfinite(r.geometric_standard_deviation))
    out.push_back({"geometric_standard_deviation", "must be at least 1 (1 is monodisperse)"});
  else if (g.name == "dlca" && r.geometric_standard_deviation != 1.0)
    out.push_back({"geometric_standard_deviation", "must be 1: the dlca generator grows monodisperse primaries"});
  if (g.name != "tunable") return;  // (a missing one is reported as missing)
  if (!std::isnan(r.fractal_dimension) && !(r.fractal_dimension >= 1.5 && r.fractal_dimension <= 2.8))
    out.push_back({"fractal_dimension", "must lie in [1.5, 2.8]"});
  if (!std::isnan(r.prefactor) && (!(r.prefactor > 0.0) || !std::isfinite(r.prefactor)))
    out.push_back({"prefactor", "must be positive"});
}

}  // namespace

const std::vector<ClusterGenerator>& cluster_generators() {
  static const std::vector<ClusterGenerator> generators{
      {"ballistic",
       {"bcca"},
       "hierarchical ballistic cluster-cluster aggregation (Jullien 1984; report figure 2), D_f ~ 1.9",
       {},
       {},
       build_ballistic},
      {"dlca",
       {},
       "diffusion-limited cluster-cluster aggregation grown by the engine with JKR contacts and Langevin "
       "dynamics (report section 3.2, figure 3), sintered or not, D_f ~ 1.65",
       {"sintering"},
       {},
       build_dlca},
      {"tunable",
       {},
       "tunable aggregation to a requested D_f and k_f (FracVAL, Moran et al. 2019)",
       {"fractal_dimension", "prefactor"},
       {"fractal_dimension", "prefactor"},
       build_tunable},
  };
  return generators;
}

const ClusterGenerator* find_cluster_generator(std::string_view name) {
  for (const ClusterGenerator& g : cluster_generators())
    if (g.name == name || contains(g.aliases, name)) return &g;
  return nullptr;
}

std::string cluster_generator_names() {
  std::string text;
  for (const ClusterGenerator& g : cluster_generators()) {
    text += (text.empty() ? "" : ", ") + std::string(g.name);
    for (std::string_view alias : g.aliases) text += " (alias " + std::string(alias) + ")";
  }
  return text;
}

bool generator_takes(std::string_view method, std::string_view field) {
  const ClusterGenerator* g = find_cluster_generator(method);
  return g && (contains(kCommonFields, field) || contains(g->fields, field));
}

std::vector<GeneratorViolation> check_generator_request(const GeneratorRequest& request,
                                                        const std::vector<std::string>& given) {
  std::vector<GeneratorViolation> out;
  const ClusterGenerator* g = find_cluster_generator(request.method);
  if (!g) {
    out.push_back(
        {"method", "unknown generator '" + request.method + "' (available: " + cluster_generator_names() + ")"});
    return out;
  }
  check_own_fields(*g, given, out);
  check_values(*g, request, out);
  return out;
}

GeneratorRequest read_generator_request(const nlohmann::ordered_json& generator,
                                        std::vector<GeneratorViolation>& violations) {
  GeneratorRequest r;
  r.method = generator.value("method", std::string("ballistic"));
  if (const ClusterGenerator* g = find_cluster_generator(r.method)) r.method = std::string(g->name);
  r.primaries = generator.value("primaries", std::size_t{1});
  r.seed = generator.value("seed", std::uint64_t{0});
  r.geometric_standard_deviation = generator.value("geometric_standard_deviation", 1.0);
  r.fractal_dimension = generator.value("fractal_dimension", r.fractal_dimension);
  r.prefactor = generator.value("prefactor", r.prefactor);
  r.sintering = generator.value("sintering", r.sintering);
  std::vector<std::string> given;
  for (const auto& [field, value] : generator.items())
    if (!contains(kCommonFields, field)) given.push_back(field);
  for (GeneratorViolation& v : check_generator_request(r, given)) violations.push_back(std::move(v));
  return r;
}

nlohmann::ordered_json generator_document(const GeneratorRequest& request) {
  Json document{{"method", request.method},
                {"primaries", request.primaries},
                {"seed", request.seed},
                {"geometric_standard_deviation", request.geometric_standard_deviation}};
  if (generator_takes(request.method, "fractal_dimension")) {
    document["fractal_dimension"] = request.fractal_dimension;
    document["prefactor"] = request.prefactor;
  }
  if (generator_takes(request.method, "sintering")) document["sintering"] = request.sintering;
  return document;
}

Cluster generate_cluster(const GeneratorRequest& request) {
  const ClusterGenerator* g = find_cluster_generator(request.method);
  if (!g)
    throw std::invalid_argument("unknown generator '" + request.method + "' (available: " + cluster_generator_names() +
                                ")");
  return g->build(request);
}

}  // namespace aerobreak
