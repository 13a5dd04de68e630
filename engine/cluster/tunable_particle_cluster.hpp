#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "engine/cluster/random_stream.hpp"
#include "engine/cluster/tunable_aggregate.hpp"
#include "engine/cluster/tunable_scaling_law.hpp"

namespace aerobreak {

struct ParticleClusterSettings {
  double overlap_tolerance = 1e-10;  // relative, see below
  // Aggregates larger than this must stay within max_deviation of the law's Rg (relative).
  std::size_t deviation_tracked_above = 0;
  double max_deviation = 0.05;
};

// A grown aggregate, or (when an aggregate above deviation_tracked_above strayed from the law by
// more than max_deviation, which ends the growth) why not; and, if the last monomer could not
// land on the law, why.
struct ParticleClusterGrowth {
  std::optional<TunableAggregate> aggregate;
  std::string failure;
  std::string last_step_shortfall;
};

// Particle-cluster stage (Filippov, Zurita & Rosner 2000; the first stage of FracVAL): the first
// two primaries touch; every further monomer goes at distance Gamma_pc from the aggregate's centre
// of mass (FracVAL eq. 6 with the aggregate's measured mass and Rg and the monomer's own), so that
// the grown aggregate of n primaries has exactly the Rg of law.gyration_radius(n, a), a being the
// geometric mean radius of all the primaries given (FracVAL's choice for this stage). The position
// lies on the contact circle of a candidate primary (tunable_contact_circle.hpp); the arcs of that
// circle where the monomer would overlap another primary (centres closer than
// (1 - overlap_tolerance)(r_j + r_k)) are computed exactly and the angle is drawn uniformly from
// the rest, candidates being taken in random order, so a step misses only when no overlap-free
// touching position exists at all. The primaries that can block a circle are found in a hashed
// cell grid; a step costs O(n) (the candidate scan), the whole growth O(n^2).
//
// When none of the next few radii still to be placed has such a position (FracVAL's swap for
// polydisperse primaries), the step cannot follow the law: at the smallest sizes no aggregate has
// the law's Rg (3 primaries at Df = 1.8, kf = 1: the law asks for slightly more than a straight
// chain's Rg), a small monomer cannot move a heavy aggregate's Rg far enough, and a compact request
// can meet a crowded shell. The monomer then goes to the distance nearest Gamma_pc that has a
// position: outward of the primary reaching farthest when Gamma_pc is beyond reach, else the first
// of Gamma_pc + 0.02 r, + 0.04 r, ... (coarser after 0.5 r) that admits one. The next steps, which
// use the measured Rg, bring the aggregate back onto the law. The radius nearest to a is kept for
// the last step, so that the final aggregate can land on the law as a monodisperse one would.
ParticleClusterGrowth grow_particle_cluster(std::vector<double> radii, const FractalLaw& law,
                                            const ParticleClusterSettings& settings, RandomStream& random);

}  // namespace aerobreak
