#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>

#include "engine/cluster/cluster.hpp"
#include "engine/dem/simulation.hpp"
#include "engine/growth/brownian_conditions.hpp"
#include "engine/growth/contact_clusters.hpp"
#include "engine/growth/rigid_far_field_growth.hpp"

namespace aerobreak {

// Diffusion-limited cluster-cluster aggregation (DLCA; Meakin 1983, Kolb, Botet & Jullien 1983)
// grown dynamically with the DEM engine, as Kempf, Pfalzner & Henning (1999, Icarus 141 388) did
// and as the report's section 3.2 / figure 3 describes: monodisperse primaries (diameter d = 1,
// mass m = 1: the reduced units of core/units.hpp) start at rest at random non-overlapping places
// in a periodic cube at the given volume fraction, move by Langevin dynamics (dem/body_forces.hpp)
// and stick by JKR contacts, until the contact graph is one connected cluster. Clusters then move
// as wholes, with the free-draining drag and noise of their primaries.
struct DiffusionLimitedParameters {
  std::size_t primary_count = 64;
  // Solid volume over box volume; sets the box edge. 0.1 %: dilute enough that clusters of a few
  // hundred primaries stay well inside the box to the end (at 1 % a cluster of 1024 has Rg ~ half
  // the box edge); the fractal dimension does not change measurably between 0.03 % and 1 % at
  // N = 256 (docs/VALIDATION.md section 7).
  double volume_fraction = 0.001;
  double gamma_over_kn = 0.01;  // reduced material (eq 7; reduced_material)
  double poisson_ratio = 0.3;
  // The report's sintering constraints: rolling (eq 18) and twisting (eq 17) resistance. On,
  // the clusters keep the open structure their collisions built (DLCA, figure 3b); off, bonded
  // primaries roll freely about each other and the clusters fold up (figure 3a).
  bool sintering = true;
  // xi_crit / d of eq 18 (with sintering). 0.1 puts the rolling spring's elastic limit,
  // k_r xi_crit^2 / (2 R*) = 8 F_c xi_crit^2 at a = a0, near the bond energy (0.9 E_b for
  // gamma/k_n = 0.01, 90 kT at the default temperature): thermal kicks do not make a sintered
  // contact roll (measured: 0.3 grows the very same clusters).
  double critical_rolling = 0.1;
  // Visco-elastic contact damping (eq 8) as a fraction of critical damping of a contact's
  // oscillation about equilibrium (as relax_cluster sets it). It takes up the energy a collision
  // releases as the contact snaps in (0.61 F_c delta_c, ~40 kT at the default E_b / kT), which
  // would otherwise rattle the new bond for a drag time m / zeta (~220 tau at the defaults).
  // Rigid-body motion of the clusters, and so their diffusion, is untouched by it.
  double damping_ratio = 0.5;
  bool tangential = true;  // Mindlin spring with Coulomb limit (eqs 10-14), either way
  double friction = 0.5;   // mu (eqs 14, 17)
  // E_b / kT (brownian_conditions). 100 is the physical value for the report's 20 nm primaries
  // (gamma = 0.05 J/m^2, E = 20 GPa, nu = 0.3 at 300 K: E_b ~ 1.54 F_c delta_c ~ 4e-19 J). It
  // also keeps the bonded clusters stiff enough: a joint's rolling spring (eq 18) lets it bend
  // thermally by theta_rms = sqrt(kT / (k_r R*)) per axis (0.03 rad here, 0.07 rad at E_b / kT =
  // 20), and a branch of n primaries swings by ~theta n^(3/2) / sqrt(3) diameters at its tip; at
  // E_b / kT = 20 that closes loops (measured at N = 64, 6 seeds: 37 % more contacts than a
  // tree, against 16 % at 100) and compacts the clusters (D_f of the growth history, n >= 8:
  // 1.94 +- 0.07 against 1.81 +- 0.06 at 100).
  double bond_energy_over_kt = 100.0;
  // Velocity persistence length of a primary, in d (brownian_conditions): a cluster of n
  // primaries keeps l_p / sqrt(n), well below its radius from n ~ 4 on. The growth time goes as
  // 1 / l_p.
  double persistence_length = 1.0;
  // Time step safety factor (dem/time_step.hpp). Half the engine's default: the growth needs
  // stable contacts that catch every collision, not an impact's energy accounting; velocity
  // Verlet is stable up to ~3 steps per period and its configurational temperature error in a
  // harmonic well, (omega dt)^2 / 4, is 1.6 % at 25.
  double steps_per_period = 25.0;
  // How clusters move while far apart.
  // - rigid: a cluster far from every other moves as one rigid body with the exact
  //   Ornstein-Uhlenbeck propagation of its free-draining Langevin dynamics (rigid_cluster.hpp),
  //   over steps as long as its gaps allow; only clusters that come within `far_field`'s
  //   encounter gap of one another run in the engine, with its contact time step
  //   (rigid_far_field_growth.hpp). The same dynamics as `engine` for clusters that are rigid,
  //   as sintered ones are (their joints bend by ~0.03 rad), at a fraction of the cost.
  // - engine: the engine moves every primary at every step the whole time (~N^2.44 cost).
  //   Unsintered clusters are not rigid: their joints roll freely, and they fold up between
  //   collisions too, which only this mode follows.
  // - rigid_when_sintered (default): rigid with sintering, engine without.
  enum class FarField { rigid_when_sintered, rigid, engine };
  FarField far_field_motion = FarField::rigid_when_sintered;
  RigidFarFieldSettings far_field;  // engine_chunk and max_steps are taken from the fields below
  bool rigid_far_field() const;
  // Plain mode: engine steps; rigid far field: rigid steps.
  std::int64_t max_steps = 50'000'000;
  std::int64_t check_interval = 1000;  // engine steps between looks at the contact graph

  // Throws std::invalid_argument naming the offending field.
  void validate() const;
};

// Where a growth run stands, at every look at the contact graph.
// Plain mode: every check_interval steps; rigid far field: at the start and whenever the number of
// clusters changes.
struct DiffusionLimitedProgress {
  std::int64_t steps = 0;    // engine steps (plain) or rigid steps (rigid far field)
  double time = 0.0;         // in tau = sqrt(m / k_n)
  std::size_t clusters = 0;  // connected components of the contact graph, monomers included
  std::size_t largest = 0;   // primaries in the largest
  // Every cluster, reassembled, largest first (e.g. for GrowthHistory); valid only during the call.
  const std::vector<ContactCluster>* components = nullptr;
};
using DiffusionLimitedProgressCallback = std::function<void(const DiffusionLimitedProgress&)>;

struct DiffusionLimitedResult {
  Cluster cluster;  // relaxed, centred on its centre of mass
  BrownianConditions conditions;
  double box_edge = 0.0;
  double time_step = 0.0;    // of the engine
  std::int64_t steps = 0;    // growth steps until one cluster remained (engine or rigid steps)
  double time = 0.0;         // growth time, tau
  std::size_t contacts = 0;  // contacts of the grown cluster (before relaxation)
  // Contacts that broke during the growth: DLCA assumes none (bonds are permanent); a few mean
  // bond_energy_over_kt is too low for the run's length.
  std::uint64_t contacts_broken = 0;
  // Contacts with the cluster's own periodic image at the end (ContactCluster::image_contacts):
  // the extracted copy lacks them. Non-zero when the cluster has grown about as large as the box.
  std::size_t image_contacts = 0;
  std::int64_t relaxation_steps = 0;
  // Engine steps times the primaries they moved: N steps in plain mode; with the rigid far field
  // those of the encounters, and `encounters` how many there were.
  std::int64_t engine_particle_steps = 0;
  std::uint64_t encounters = 0;
  std::uint64_t overlaps = 0;  // RigidFarFieldOutcome::overlaps
};

// Throws std::invalid_argument for bad parameters and std::runtime_error, naming how many
// clusters remain, if max_steps pass before one cluster holds every primary. The same
// parameters and seed give the same cluster on the same build.
DiffusionLimitedResult grow_diffusion_limited(const DiffusionLimitedParameters& parameters, std::uint64_t seed,
                                              const DiffusionLimitedProgressCallback& progress = {});

// The cluster alone.
Cluster diffusion_limited_aggregation(const DiffusionLimitedParameters& parameters, std::uint64_t seed,
                                      const DiffusionLimitedProgressCallback& progress = {});

}  // namespace aerobreak
