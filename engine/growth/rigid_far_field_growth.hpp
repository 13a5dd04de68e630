#pragma once
#include <cstdint>
#include <functional>
#include <vector>

#include "engine/contact/model_spec.hpp"
#include "engine/core/material.hpp"
#include "engine/core/particles.hpp"
#include "engine/dem/simulation.hpp"
#include "engine/growth/contact_clusters.hpp"
#include "engine/growth/rigid_cluster.hpp"

namespace aerobreak {

// How the accelerated growth hands clusters between the rigid-body propagator and the engine.
struct RigidFarFieldSettings {
  double encounter_gap = 0.25;       // surface gap (d) below which two clusters go to the engine
  double release_gap = 0.5;          // gap between every two clusters of an encounter before it ends
  double settle_time = 50.0;         // time (tau) without a contact made or broken before it ends
  double step_fraction = 0.15;       // rms reach of a rigid step over the cluster's smallest gap
  double search_gap = 3.0;           // particle pairs within this gap are looked at one by one
  std::int64_t engine_chunk = 1000;  // engine steps at most between looks
  std::int64_t max_steps = 0;        // rigid steps at most
};

struct RigidFarFieldOutcome {
  ContactCluster grown;  // members as particle indices, reassembled centres
  double tension = 0.0;  // largest contact tension (-overlap) the grown cluster had when frozen
  double time = 0.0;
  std::int64_t rigid_steps = 0;
  std::int64_t engine_particle_steps = 0;  // engine steps times the primaries they moved
  std::uint64_t encounters = 0;
  std::uint64_t contacts_broken = 0;
  // Rigid clusters found overlapping another after a rigid step: the Gaussian step overshot the
  // gap (probability ~1e-6 per close pair and step at the default step fraction). The engine
  // takes them over at that overlap.
  std::uint64_t overlaps = 0;
};

// One look at the growth: every cluster, reassembled, largest first.
struct RigidFarFieldLook {
  std::int64_t rigid_steps = 0;
  double time = 0.0;
  const std::vector<ContactCluster>* clusters = nullptr;
};

// Grows until one cluster is left (diffusion_limited_aggregation.hpp, rigid_far_field). Every
// primary starts as a cluster of one. Each step: the smallest gap from every cluster to any other
// (GroupProximitySearch); clusters closer than encounter_gap, with the encounters they touch,
// become one encounter, a Simulation of just their primaries (same box, time step, contact model
// and bath; contacts within each cluster re-formed through `base.initial_bond_gap`); the step is
// the largest that keeps every rigid cluster's rms reach (step_for_reach) within step_fraction of
// its gap and, while encounters run, a whole number of engine steps; rigid clusters advance by it
// exactly (propagate), encounters by that many engine steps. An encounter whose contacts have not
// changed for settle_time and whose clusters are all release_gap apart turns back into rigid
// clusters. `look` is called at the start and whenever the number of clusters changes. Throws
// std::runtime_error, naming the clusters left, after max_steps rigid steps.
RigidFarFieldOutcome grow_with_rigid_far_field(const Particles& primaries, const Material& material,
                                               const ContactModelSpec& model, const SimulationSettings& base,
                                               const PrimaryBath& bath, const RigidFarFieldSettings& settings,
                                               std::uint64_t seed,
                                               const std::function<void(const RigidFarFieldLook&)>& look);

}  // namespace aerobreak
