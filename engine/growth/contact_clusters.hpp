#pragma once
#include <cstddef>
#include <utility>
#include <vector>

#include "engine/core/vec3.hpp"
#include "engine/dem/simulation.hpp"

namespace aerobreak {

// One connected component of a run's particle-particle contact graph, reassembled in one piece:
// in a periodic box its members may sit on opposite faces, or have been wrapped different numbers
// of times, so neither the wrapped nor the unwrapped positions keep it together. The reassembly
// walks a spanning tree of the contacts from the lowest-numbered member (which keeps its unwrapped
// position) and places each newly reached member at its parent plus their nearest-image
// separation, which a contact (shorter than half the box) always is.
struct ContactCluster {
  std::vector<std::size_t> members;  // particle indices, in the order the tree reached them
  std::vector<Vec3> position;        // reassembled centres, one per member
  std::size_t contacts = 0;          // contacts between members
  // Contacts that close a loop around the periodic box: the cluster touches its own image. The
  // reassembled cluster cannot keep them (it is one copy, not a box-spanning network), so they
  // are missing from `position`'s geometry. 0 in open space.
  std::size_t image_contacts = 0;
};

// Particle-particle contacts of the run as (i, j) pairs, i < j.
std::vector<std::pair<std::size_t, std::size_t>> contact_edges(const Simulation& simulation);

// All components, largest first (ties: lowest first member first); single particles included.
std::vector<ContactCluster> contact_clusters(const Simulation& simulation);

}  // namespace aerobreak
