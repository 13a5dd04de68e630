#pragma once
#include <cstddef>
#include <cstdint>
#include <stdexcept>

#include "engine/cluster/cluster.hpp"
#include "engine/cluster/tunable_scaling_law.hpp"

namespace aerobreak {

// Parameters of the tunable generator. Primary diameters are lognormal with geometric mean
// `geometric_mean_diameter` and geometric standard deviation `geometric_standard_deviation`
// (ln d ~ Normal(ln d_g, ln sigma_g)); sigma_g = 1 (the default) is monodisperse.
struct TunableAggregationParameters {
  std::size_t primary_count = 0;
  double fractal_dimension = 1.8;  // Df, 1.5 to 2.8
  double prefactor = 1.3;          // kf
  double geometric_mean_diameter = 1.0;
  double geometric_standard_deviation = 1.0;
  // Which Rg the law constrains; FracVAL's (solid spheres) by default, so its (Df, kf) carry over.
  GyrationConvention gyration_convention = GyrationConvention::solid_spheres;
  // Aggregates of up to this many primaries (at least 3) are grown monomer by monomer.
  std::size_t particle_cluster_size = 32;
  // Trial placements (pair, contact point, orientation) per cluster-cluster join; after that the
  // second aggregate, if a particle-cluster group, is regrown afresh (up to max_join_rebuilds
  // times), and then the union is grown monomer by monomer instead.
  int max_cluster_cluster_attempts = 5000;
  int max_join_rebuilds = 3;
  // Fresh starts of a particle-cluster growth that is the whole cluster, when its last monomer
  // could not land on the law.
  int max_particle_cluster_restarts = 4;
  // Largest relative deviation from the law's Rg tolerated where the law cannot be followed
  // exactly: for three primaries (tunable_feasibility.hpp) and for aggregates larger than
  // particle_cluster_size grown monomer by monomer. 5 % in Rg is about 10 % in kf, the precision
  // to which measured prefactors are known.
  double max_intermediate_deviation = 0.05;
};

// The requested (Df, kf, N) could not be built: the message names the stage (particle-cluster or
// cluster-cluster), the aggregate sizes and the reason (Gamma^2 < 0 or no overlap-free contact
// position: too compact; Gamma beyond every primary's reach: too open).
class UnreachableFractalParameters : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Tunable fractal aggregate after FracVAL (Moran, Fuentes, Liu & Yon 2019, Comput. Phys. Commun.
// 239 225), from the tunable particle-cluster and cluster-cluster aggregation of Filippov, Zurita &
// Rosner (2000, J. Colloid Interface Sci. 229 261). The result obeys N = kf (Rg / a)^Df exactly (to
// round-off), with a the geometric mean radius of its primaries and Rg in the chosen convention
// (tunable_scaling_law.hpp).
//
// The primaries (lognormal radii, in the random order of the draw) are split in halves
// recursively, as in ballistic_cluster_cluster_aggregation, down to groups of at most
// particle_cluster_size. Each group is grown by particle-cluster aggregation
// (tunable_particle_cluster.hpp), every monomer at the distance Gamma_pc that puts the grown
// aggregate on the law, and the groups are joined pairwise by cluster-cluster aggregation
// (tunable_cluster_cluster.hpp), every join placing the two centres of mass at the distance
// Gamma_cc that gives the union the law's Rg. So every aggregate formed by a join obeys the law
// exactly (with its own n and a), and so does every monomer-by-monomer aggregate wherever an
// overlap-free touching position exists at Gamma_pc. Where none does the monomer goes to the
// nearest distance that has one and the next steps return to the law; this is accepted in groups
// (up to particle_cluster_size primaries: polydisperse groups and the smallest sizes cannot
// always follow it) but an aggregate grown past that size may stray at most
// max_intermediate_deviation, and the law for three primaries must lie within the same tolerance
// of what three touching primaries can have (tunable_feasibility.hpp); otherwise the request is
// unreachable. A join that finds no placement in max_cluster_cluster_attempts (compact requests,
// Df >~ 2.5: the halves would have to interpenetrate more than their structure allows) is retried
// with a regrown second group, then replaced by growing the union monomer by monomer, as is every
// later aggregate at least as large.
//
// Before returning, the result is checked: Rg against a (N / kf)^(1 / Df) to a relative 1e-9
// (construction is exact, and round-off in the placements and sums stays below 1e-12), no two
// primaries' centres closer than (1 - 1e-9)(r_i + r_j), and one connected contact network (contacts
// within a relative 1e-9); a failed check throws std::runtime_error. The result is centred on its
// centre of mass, its primaries listed along their neighbours (ordered_along_neighbours); the same
// parameters and seed give bit-identical output on the same build.
//
// Throws std::invalid_argument naming the parameter for primary_count < 1, Df outside [1.5, 2.8],
// a non-positive or non-finite kf or diameter, sigma_g < 1, particle_cluster_size < 3,
// max_cluster_cluster_attempts < 1 or another limit below 0; UnreachableFractalParameters when the
// requested structure cannot be built (including N = 1 or 2, whose Rg is fixed, unless it happens
// to match the law).
//
// Reached (N = 1024, 4 seeds per point, kf in steps of 0.1): monodisperse, the whole three-primary
// window at 5 %: Df = 1.5: kf >= 1.2; 1.6: >= 1.1; 1.8: 1.0-1.7; 2.0: 0.9-1.7; 2.3: 0.7-1.5;
// 2.6: 0.6-1.4; 2.8: 0.5-1.3. Lognormal sigma_g = 1.3: the same up to Df = 2.3; at 2.6 kf 0.6-1.1
// and at 2.8 kf 0.5-0.9 for most seeds, not all (joins fail and the monomer-by-monomer growth
// meets crowded shells). sigma_g = 1.6: Df up to 2.0 (kf 0.9-1.3), 2.3 only at kf 0.7-0.8.
Cluster tunable_cluster_aggregation(const TunableAggregationParameters& parameters, std::uint64_t seed);

}  // namespace aerobreak
