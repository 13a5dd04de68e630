#pragma once
#include <cstddef>
#include <vector>

#include "engine/cluster/cluster.hpp"
#include "engine/core/vec3.hpp"

namespace aerobreak {

// Structure of one cluster. Masses are proportional to r^3 (one material density); Rg is that of
// the primaries' centres as point masses, the convention of the fractal-aggregate literature
// (a dimer of unit-diameter spheres has Rg = 0.5).
struct ClusterAnalysis {
  std::size_t primary_count = 0;
  Vec3 centre_of_mass;
  double radius_of_gyration = 0.0;
  double maximum_extent = 0.0;
  std::size_t contact_count = 0;             // touching pairs, see find_contacts
  std::size_t deep_overlap_count = 0;        // of those, pairs overlapping deeper than the tolerance
  double mean_coordination_number = 0.0;     // 2 * contact_count / primary_count
  std::vector<std::size_t> component_sizes;  // connected components of the contacts, largest first
  double filling_factor = 0.0;
  double porosity = 0.0;
  double mass_radius_dimension = 0.0;
};

// Every analysis function throws std::invalid_argument for an empty cluster.
Vec3 centre_of_mass(const Cluster& cluster);
double radius_of_gyration(const Cluster& cluster);

// Largest distance between two points of the cluster: max over pairs of |x_i - x_j| + r_i + r_j
// (and at least the largest single diameter). Exact; pairs are visited in decreasing order of
// rho_i = |x_i - c| + r_i and cut off once rho_i + rho_j cannot beat the best so far. Worst case
// O(N^2) (every primary on one sphere about the centre); for fractal clusters only the outer
// primaries pair up.
double maximum_extent(const Cluster& cluster);

// Filling factor inside the radius-of-gyration sphere: phi = sum_i r_i^3 / R^3 with
// R = sqrt(5/3) Rg, the radius of the uniform solid sphere whose Rg equals the cluster's; the
// porosity is 1 - phi. Both are NaN for a single primary (Rg = 0).
double filling_factor(const Cluster& cluster);

// Fractal dimension of one cluster from its mass-radius relation M(r) ~ r^D, with M(r) the mass
// within distance r of a primary's centre, averaged over primaries as centres (mass-weighted; at
// most 2048 centres, an even stride through the cluster, so the cost is O(min(N, 2048) N)). This
// is the cumulative pair-correlation form of the mass-radius relation (Forrest & Witten 1979;
// Jullien & Botet 1987). M(r) about the centre of mass alone is not used: in a cluster-cluster
// aggregate the centre of mass sits in the void between the last two sub-clusters (for a 4096-
// primary BCCA cluster nothing lies within 10 d of it), so that curve measures the halves'
// separation, not the internal scaling. Fitted in log-log at 16 logarithmically spaced r from 2
// mean primary diameters to Rg/2: below, the count is dominated by the discrete first neighbours;
// above, the cluster's edge cuts M(r) off and the local slope falls (to ~1.5 at r = Rg for BCCA).
// NaN when Rg < 8 mean diameters (less than a factor 2 of range).
double mass_radius_dimension(const Cluster& cluster);

// All of the above; contacts use the relative tolerance of find_contacts.
ClusterAnalysis analyse_cluster(const Cluster& cluster, double contact_tolerance = 1e-3);

}  // namespace aerobreak
