#pragma once
#include "engine/cluster/cluster.hpp"

namespace aerobreak {

// The cluster with its primaries listed breadth-first over the graph of neighbours, the primaries
// whose surfaces are within relative_reach (r_i + r_j) of each other (find_contacts with that
// tolerance: touching ones and those a neighbour-list skin away), starting from a primary at one
// end of the graph (the last one reached from the first primary, then the last one reached from
// that one); further components follow the first. Neighbours end up close in index: a fractal
// aggregate is thin, so few primaries lie at the same number of steps from the start. A force
// pass over the pairs in index order then works on a narrow band of particles, which the
// simulation's wavefront needs to keep several steps in the caches.
Cluster ordered_along_neighbours(const Cluster& cluster, double relative_reach = 0.5);

}  // namespace aerobreak
