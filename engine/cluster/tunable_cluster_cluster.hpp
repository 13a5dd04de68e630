#pragma once
#include <optional>
#include <string>

#include "engine/cluster/random_stream.hpp"
#include "engine/cluster/tunable_aggregate.hpp"
#include "engine/cluster/tunable_scaling_law.hpp"

namespace aerobreak {

// What a join produced: the aggregate, or why there is none.
struct TunableJoin {
  std::optional<TunableAggregate> aggregate;
  std::string failure;
};

// Cluster-cluster stage of FracVAL: joins aggregate b to aggregate a with their centres of mass
// Gamma_cc apart (FracVAL eq. 6 with both aggregates' measured masses and radii of gyration), so
// that the union has exactly the law's Rg for its n_a + n_b primaries and their geometric mean
// radius, with one primary i of a touching one primary j of b and no other pair closer than
// (1 - overlap_tolerance)(r + r').
//
// A pair (i, j) can touch with the centres Gamma apart only if the four lengths |x_i - c_a|,
// r_i + r_j, |x_j - c_b| and Gamma close a quadrilateral (each at most the sum of the other three);
// b's primaries are sorted by distance from c_b so that each i's admissible j form one range found
// by binary search (FracVAL's candidate list, O(N log N)). Each attempt draws an admissible pair
// uniformly, then the contact point of j uniformly over the zone of the sphere |x - x_i| = r_i +
// r_j from which c_b can lie at distance Gamma from c_a and |x_j - c_b| from x_j, then c_b
// uniformly on the circle that leaves, then b's orientation uniformly among those putting x_j
// there; the attempt is kept if no primary of b overlaps a (hashed cell grid). Fails (with the
// reason) when Gamma_cc^2 <= 0, when no pair is admissible, or after max_attempts attempts.
TunableJoin join_aggregates(const TunableAggregate& a, const TunableAggregate& b, const FractalLaw& law,
                            int max_attempts, double overlap_tolerance, RandomStream& random);

}  // namespace aerobreak
