#include "engine/cluster/tunable_aggregation.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "engine/cluster/cluster_contacts.hpp"
#include "engine/cluster/neighbour_order.hpp"
#include "engine/cluster/random_stream.hpp"
#include "engine/cluster/tunable_aggregate.hpp"
#include "engine/cluster/tunable_cluster_cluster.hpp"
#include "engine/cluster/tunable_feasibility.hpp"
#include "engine/cluster/tunable_particle_cluster.hpp"

namespace aerobreak {
namespace {

// Placements accept centre distances down to (1 - 1e-10)(r_i + r_j), so that touching pairs left
// at round-off distance are not counted as overlaps; the final check allows ten times more.
constexpr double placement_overlap_tolerance = 1e-10;
constexpr double verification_overlap_tolerance = 1e-9;
constexpr double verification_gyration_tolerance = 1e-9;

std::string describe(double value) {
  std::ostringstream out;
  out.precision(4);
  out << value;
  return out.str();
}

void validate(const TunableAggregationParameters& p) {
  const auto fail = [](const std::string& what) { throw std::invalid_argument("tunable aggregation: " + what); };
  if (p.primary_count < 1) fail("primary_count must be >= 1");
  if (!(p.fractal_dimension >= 1.5 && p.fractal_dimension <= 2.8)) {
    fail("fractal_dimension must lie in [1.5, 2.8], got " + describe(p.fractal_dimension));
  }
  if (!(p.prefactor > 0.0) || !std::isfinite(p.prefactor)) {
    fail("prefactor must be positive and finite, got " + describe(p.prefactor));
  }
  if (!(p.geometric_mean_diameter > 0.0) || !std::isfinite(p.geometric_mean_diameter)) {
    fail("geometric_mean_diameter must be positive and finite, got " + describe(p.geometric_mean_diameter));
  }
  if (!(p.geometric_standard_deviation >= 1.0) || !std::isfinite(p.geometric_standard_deviation)) {
    fail("geometric_standard_deviation must be >= 1 and finite, got " + describe(p.geometric_standard_deviation));
  }
  if (p.particle_cluster_size < 3) fail("particle_cluster_size must be >= 3");
  if (p.max_cluster_cluster_attempts < 1) fail("max_cluster_cluster_attempts must be >= 1");
  if (p.max_join_rebuilds < 0) fail("max_join_rebuilds must be >= 0");
  if (p.max_particle_cluster_restarts < 0) fail("max_particle_cluster_restarts must be >= 0");
  if (!(p.max_intermediate_deviation >= 0.0)) fail("max_intermediate_deviation must be >= 0");
}

// The law's Rg for an aggregate: its own primary count and geometric mean radius.
double law_gyration_radius(const FractalLaw& law, const TunableAggregate& a) {
  const auto n = static_cast<double>(a.size());
  return law.gyration_radius(n, std::exp(a.log_radius_sum / n));
}

std::string context(const TunableAggregationParameters& p) {
  std::ostringstream out;
  out << "tunable aggregation (Df = " << p.fractal_dimension << ", kf = " << p.prefactor << ", N = " << p.primary_count
      << ", sigma_g = " << p.geometric_standard_deviation << "): ";
  return out.str();
}

class Builder {
 public:
  Builder(const TunableAggregationParameters& p, const FractalLaw& law, RandomStream& random)
      : law_(law),
        random_(random),
        context_(context(p)),
        settings_{placement_overlap_tolerance, p.particle_cluster_size, p.max_intermediate_deviation},
        particle_cluster_limit_(p.particle_cluster_size),
        total_(p.primary_count),
        max_attempts_(p.max_cluster_cluster_attempts),
        max_rebuilds_(p.max_join_rebuilds),
        max_restarts_(p.max_particle_cluster_restarts) {}

  // The aggregate of radii [first, first + count): halves joined by cluster-cluster aggregation,
  // down to groups grown by particle-cluster aggregation. A join that finds no placement is tried
  // again with the second half regrown afresh when that half is a particle-cluster group (cheap;
  // larger halves are not rebuilt, which would multiply the work level by level). If the join
  // still fails (compact requests: the halves would have to interpenetrate more than their
  // structure allows) the union is grown monomer by monomer instead, and so is every later
  // aggregate at least as large, where joins would fail the same way.
  TunableAggregate build(const std::vector<double>& radii, std::size_t first, std::size_t count) {
    if (count <= particle_cluster_limit_) return grow(radii, first, count);
    const std::size_t larger = count - count / 2;
    const TunableAggregate a = build(radii, first, larger);
    const bool regrowable = count / 2 <= particle_cluster_limit_;
    TunableAggregate b = build(radii, first + larger, count / 2);
    for (int rebuild = 0;; ++rebuild) {
      TunableJoin joined = join_aggregates(a, b, law_, max_attempts_, placement_overlap_tolerance, random_);
      if (joined.aggregate) return std::move(*joined.aggregate);
      join_failure_ = std::move(joined.failure);
      if (!regrowable || rebuild == max_rebuilds_) break;
      b = grow(radii, first + larger, count / 2);
    }
    particle_cluster_limit_ = std::max(particle_cluster_limit_, count);
    return grow(radii, first, count);
  }

  // Why the last particle-cluster growth ended off the law (empty if it did not).
  const std::string& last_growth_shortfall() const { return growth_shortfall_; }
  // The last failed join, as context for the above (empty if none).
  std::string join_note() const {
    return join_failure_.empty() ? std::string()
                                 : "; it had taken over from the cluster-cluster stage after " + join_failure_;
  }

 private:
  // A growth that is the whole cluster must end on the law: it is restarted when it does not.
  TunableAggregate grow(const std::vector<double>& radii, std::size_t first, std::size_t count) {
    const std::vector<double> group(radii.begin() + static_cast<std::ptrdiff_t>(first),
                                    radii.begin() + static_cast<std::ptrdiff_t>(first + count));
    ParticleClusterGrowth grown = grow_particle_cluster(group, law_, settings_, random_);
    for (int restart = 0;
         restart < max_restarts_ && count == total_ && grown.aggregate && !grown.last_step_shortfall.empty();
         ++restart) {
      grown = grow_particle_cluster(group, law_, settings_, random_);
    }
    if (!grown.aggregate) {
      const std::string what = "the aggregates on the way cannot follow the scaling law; ";
      throw UnreachableFractalParameters(context_ + what + "particle-cluster stage, " + grown.failure + join_note());
    }
    growth_shortfall_ = std::move(grown.last_step_shortfall);
    return std::move(*grown.aggregate);
  }

  const FractalLaw& law_;
  RandomStream& random_;
  std::string context_;
  ParticleClusterSettings settings_;
  std::size_t particle_cluster_limit_;
  std::size_t total_;
  int max_attempts_;
  int max_rebuilds_;
  int max_restarts_;
  std::string growth_shortfall_;
  std::string join_failure_;
};

// A monomer or a dimer has no free geometry: it is returned only if its fixed Rg obeys the law.
TunableAggregate smallest(const std::vector<double>& radii, const FractalLaw& law,
                          const TunableAggregationParameters& p, RandomStream& random) {
  std::vector<Vec3> x{Vec3{}};
  if (radii.size() == 2) x.push_back((radii[0] + radii[1]) * random.unit_vector());
  TunableAggregate a = centred_aggregate(std::move(x), radii, law.convention);
  const double target = law_gyration_radius(law, a);
  if (std::abs(a.gyration_radius / target - 1.0) > verification_gyration_tolerance) {
    throw UnreachableFractalParameters(
        context(p) + std::to_string(radii.size()) + " primaries have a fixed Rg = " + describe(a.gyration_radius) +
        ", the scaling law asks for " + describe(target) + "; it can be imposed from three primaries on");
  }
  return a;
}

// Joins are exact, so a final aggregate off the law was grown monomer by monomer and its last
// monomer could not be put at Gamma_pc: the request is unreachable at this N.
void require_law(const TunableAggregate& aggregate, const FractalLaw& law, const TunableAggregationParameters& p,
                 const Builder& builder) {
  const double target = law_gyration_radius(law, aggregate);
  if (std::abs(aggregate.gyration_radius / target - 1.0) <= verification_gyration_tolerance) return;
  throw UnreachableFractalParameters(context(p) + "the scaling law's Rg = " + describe(target) +
                                     " cannot be reached (got " + describe(aggregate.gyration_radius) +
                                     "); particle-cluster stage, " + builder.last_growth_shortfall() +
                                     builder.join_note());
}

void verify(const Cluster& cluster, const FractalLaw& law) {
  const double rg = gyration_radius(cluster, law.convention);
  const double target = law.gyration_radius(static_cast<double>(cluster.size()), geometric_mean_radius(cluster.radius));
  if (!(std::abs(rg / target - 1.0) <= verification_gyration_tolerance)) {
    throw std::runtime_error("tunable aggregation: check failed: Rg = " + describe(rg) +
                             " differs from the scaling law's " + describe(target));
  }
  const ContactGraph graph = find_contacts(cluster, verification_overlap_tolerance);
  if (graph.deep_overlap_count > 0) {
    throw std::runtime_error("tunable aggregation: check failed: " + std::to_string(graph.deep_overlap_count) +
                             " overlapping pairs");
  }
  const std::size_t components = connected_component_sizes(cluster.size(), graph.contacts).size();
  if (components != 1) {
    throw std::runtime_error("tunable aggregation: check failed: " + std::to_string(components) +
                             " connected components");
  }
}

}  // namespace

Cluster tunable_cluster_aggregation(const TunableAggregationParameters& parameters, std::uint64_t seed) {
  validate(parameters);
  RandomStream random(seed);
  const std::vector<double> radii = random.lognormal_radii(parameters.primary_count, parameters.geometric_mean_diameter,
                                                           parameters.geometric_standard_deviation);
  const FractalLaw law{parameters.fractal_dimension, parameters.prefactor, parameters.gyration_convention};

  TunableAggregate aggregate;
  if (radii.size() <= 2) {
    aggregate = smallest(radii, law, parameters, random);
  } else {
    if (const std::optional<std::string> shortfall =
            three_primary_shortfall(law, parameters.max_intermediate_deviation)) {
      throw UnreachableFractalParameters(context(parameters) + *shortfall);
    }
    Builder builder(parameters, law, random);
    aggregate = builder.build(radii, 0, radii.size());
    require_law(aggregate, law, parameters, builder);
  }
  Cluster cluster{std::move(aggregate.position), std::move(aggregate.radius)};
  verify(cluster, law);
  return ordered_along_neighbours(cluster);
}

}  // namespace aerobreak
