#pragma once
#include <algorithm>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "engine/contact/model_spec.hpp"
#include "engine/core/material_table.hpp"
#include "engine/core/particles.hpp"
#include "engine/dem/body_forces.hpp"
#include "engine/dem/contact_forces.hpp"
#include "engine/dem/energy_budget.hpp"
#include "engine/dem/neighbor_list.hpp"
#include "engine/dem/particle_drift.hpp"
#include "engine/dem/step_chooser.hpp"
#include "engine/dem/time_step.hpp"
#include "engine/dem/wall.hpp"
#include "engine/dem/wavefront.hpp"
#include "engine/neighbor/periodic_box.hpp"

namespace aerobreak {

struct SimulationSettings {
  double time_step = 0.0;          // 0: automatic, from recommend_time_step
  double steps_per_period = 50.0;  // safety factors of the automatic step (TimeStepFactors)
  double steps_per_break_overlap = 10.0;
  double speed_scale = 0.0;  // largest speed the automatic step must resolve; 0: from the initial state
  // The automatic step chosen again during the run from the speeds of the moment (StepChooser,
  // docs/MODEL.md 9.2), never longer than the contact period allows at the speed scale; false:
  // one step for the whole run, at the speed scale. Only where the step has an adhesion loop to
  // resolve (steps_per_break_overlap > 0, a law with a tensile range), in open space and without
  // Langevin forces.
  bool adaptive_time_step = true;
  double step_headroom = 0.15;  // StepChooser's headroom (docs/MODEL.md 9.2)
  double skin = 0.0;            // Verlet skin; 0: automatic, from the speed scale and time step
  bool brute_force_neighbors = false;
  // Pairs whose surfaces are closer than this at the start are in contact from the start: a
  // cluster built at touching distance is bonded whatever the round-off in its coordinates.
  double initial_bond_gap = 0.0;
  BodyForces body;
  // Force passes of this many consecutive steps run together as a wavefront over the particles
  // (ContactForces::add_pair_forces), so that the arrays of a system too large for the
  // caches are fetched once for several steps; 1: one step at a time. The results are the same.
  // Only from wavefront_min_particles on: a smaller system's arrays (about 270 bytes a particle)
  // stay in the caches anyway, and one step at a time is faster (docs/PERFORMANCE.md).
  int wavefront_depth = 16;
  std::size_t wavefront_min_particles = 24000;
  // A wavefront is only as deep as no particle can leave the neighbour list's skin during it,
  // taking each step to move a particle at most this many times as far as the last step moved
  // any; one in which a particle does leave is undone, and its steps run one at a time.
  double wavefront_margin = 2.0;
  // A box [0, L) periodic along all three axes (no walls or gravity then): pairs interact
  // through their nearest images, and positions are wrapped back into the box whenever the
  // neighbour list is rebuilt (Simulation::images counts the wraps). Every edge must exceed twice
  // the largest diameter plus the interaction margin and the skin.
  std::optional<PeriodicBox> periodic;
};

// A DEM run: spheres, walls, one contact model, velocity-Verlet integration of translation and
// rotation. Forces at step n+1 use the positions x(n+1) and the half-step velocities v(n+1/2).
class Simulation {
 public:
  Simulation(Particles particles, std::vector<Material> materials, std::vector<Wall> walls, ContactModelSpec model,
             SimulationSettings settings = {});

  void step();
  // Runs `steps` steps, or fewer: it stops after the first step that brings the clock to `until`
  // or past it. Where a run stops does not change the trajectory: runs in stretches give the
  // states of one run to the last bit.
  void run(std::int64_t steps, double until = std::numeric_limits<double>::infinity());

  // In a periodic box the positions are those wrapped at the last neighbour rebuild (images()).
  const Particles& particles() const { return particles_; }
  // Velocities and angular velocities may be changed between steps (e.g. to launch an impact);
  // positions may not: build a new Simulation for a new configuration.
  Particles& particles() { return particles_; }

  // The step of the last drift (of the next one before the first step).
  double time_step() const { return dt_; }
  // The automatic step at the speed scale (also computed for a fixed step: its contact period).
  const TimeStepEstimate& time_step_estimate() const { return estimate_; }
  bool adaptive_time_step() const { return chooser_ != nullptr; }
  const StepHistory& step_history() const { return history_; }
  double time() const { return time_; }
  std::int64_t step_count() const { return steps_; }

  EnergyBudget energy() const;
  // A live contact's energy scales (docs/IMPACT.md section 4): what its springs store above the
  // rest of its normal law (its zero-load overlap), and the work from that rest to where it lets
  // go, E_break (0 for a contact without a tensile range).
  struct ContactReserve {
    double above_rest = 0.0;
    double to_break = 0.0;
  };
  ContactReserve contact_reserve(const ContactState& contact) const;
  // The energy the adhesion loop of a contact of particle i with wall w dissipates, from forming at
  // touching to letting go at -delta_b (docs/MODEL.md 3.4): particle i, arriving slower than that,
  // stays (0 for a wall without adhesion).
  double wall_loop_energy(std::size_t i, std::size_t w) const;
  ContactsView contacts() const { return {pair_pool_, wall_pool_}; }
  const ContactEvents& pair_events() const { return pair_events_; }
  const ContactEvents& wall_events() const { return wall_events_; }
  std::uint64_t neighbor_builds() const { return neighbors_->builds(); }
  // Steps run in wavefronts (SimulationSettings::wavefront_depth), and wavefronts undone because a
  // particle left the skin during one (their steps then ran one at a time).
  std::uint64_t wavefront_steps() const { return wavefront_.steps(); }
  std::uint64_t wavefronts_undone() const { return wavefront_.undone(); }
  std::size_t neighbor_pairs() const { return neighbors_->pairs().pairs(); }
  const std::vector<Wall>& walls() const { return walls_; }
  const ContactModelSpec& model() const { return spec_; }
  const BodyForces& body_forces() const { return settings_.body; }
  const MaterialTable& materials() const { return materials_; }

  const std::optional<PeriodicBox>& periodic_box() const { return settings_.periodic; }
  // Box lengths by which each particle has been wrapped (all zero in open space).
  const std::vector<ImageCount>& images() const { return images_; }
  // Positions as if never wrapped: x_i + n_i L. Equal to the positions in open space.
  std::vector<Vec3> unwrapped_positions() const;
  // x_j - x_i, through the nearest image in a periodic box.
  Vec3 separation(std::size_t i, std::size_t j) const;

 private:
  friend class Wavefront;
  class ForcePass;
  ParticleDrift verlet_step(ParticleDrift& drift, bool more);
  void advance_clock();
  void prepare_forces(ParticleDrift& drift);
  void start_step_chooser();
  void choose_step();
  void commit_step();
  bool switching_step() const { return next_dt_ != dt_; }
  // Of the next `most` steps at the present step: how many, and whether the last of them brings
  // the clock to `until` (the clock adds the step once per step, as counted here).
  std::int64_t steps_before(double until, std::int64_t most, bool& reaches) const;
  double choice_expires() const { return choice_expires_; }
  double timing_weight() const { return 2.0 * dt_ / (dt_ + next_dt_); }
  ParticleDrift compute_forces(bool rebuild, double formation_gap, bool integrate);
  void add_pair_forces(double formation_gap, const std::vector<ContactForces::Pass>& passes);
  void rebuild_neighbors();
  void require_list_for_particles() const;
  // kick_and_drift compiled for the case at hand: watched or not, the step changing or not.
  template <int Kicks>
  ParticleDrift integrate(std::size_t begin, std::size_t end) {
    if (!chooser_) return kick_and_drift<Kicks, false, false>(begin, end);
    return switching_step() ? kick_and_drift<Kicks, true, true>(begin, end)
                            : kick_and_drift<Kicks, true, false>(begin, end);
  }
  template <int Kicks, bool Watch, bool Switching>
  ParticleDrift kick_and_drift(std::size_t begin, std::size_t end);
  void kick();
  void set_half_steps(double dt, std::vector<double>& per_mass, std::vector<double>& per_inertia) const;
  // Half a step's velocity change of particle i under the force and torque given, with the half
  // steps over mass and inertia of one of the two steps a kick can belong to.
  static void half_kick(std::size_t i, Vec3& velocity, Vec3& spin, const Vec3& force, const Vec3& torque,
                        const double* per_mass, const double* per_inertia) {
    velocity += per_mass[i] * force;
    spin += per_inertia[i] * torque;
  }
  template <class Space>
  void add_van_der_waals(const Space& separation_of);
  void wrap_positions();
  void close_lost_contacts(const std::vector<std::int32_t>& lost);
  double interaction_margin() const;
  double speed_scale() const;

  Particles particles_;
  MaterialTable materials_;
  std::vector<Wall> walls_;
  ContactModelSpec spec_;
  SimulationSettings settings_;
  std::unique_ptr<ContactForces> pair_forces_;
  std::vector<std::unique_ptr<ContactForces>> wall_forces_;
  std::vector<std::vector<std::int32_t>> wall_slots_;
  std::unique_ptr<VerletNeighborList> neighbors_;
  ContactPool pair_pool_{false};
  ContactPool wall_pool_{true};
  ContactEvents pair_events_;
  ContactEvents wall_events_;
  DissipationTally tally_;
  TimeStepEstimate estimate_;
  std::unique_ptr<StepChooser> chooser_;
  double dt_ = 0.0;       // the step of the last drift: the laws' step and the closing half kick's
  double next_dt_ = 0.0;  // the step of the next drift and of the opening half kick
  TimeStepLimit limit_ = TimeStepLimit::contact_period;
  TimeStepLimit next_limit_ = TimeStepLimit::contact_period;
  double choice_expires_ = std::numeric_limits<double>::infinity();  // the last choice holds until then
  StepHistory history_;
  double time_ = 0.0;
  std::int64_t steps_ = 0;
  double external_work_ = 0.0;
  std::vector<double> half_step_per_mass_;       // dt / (2 m_i)
  std::vector<double> half_step_per_inertia_;    // dt / (2 I_i)
  std::vector<double> next_half_step_per_mass_;  // the same for next_dt_ while it differs
  std::vector<double> next_half_step_per_inertia_;
  std::vector<ImageCount> images_;
  double van_der_waals_energy_ = 0.0;
  Wavefront wavefront_;
  // The rest energy of the last contact contact_reserve() was asked about, by its law and
  // constants: the contacts of a cluster of equal primaries share them.
  struct RestEnergy {
    const ContactForces* law = nullptr;
    ContactConstants constants;
    double energy = 0.0;
  };
  mutable RestEnergy last_rest_;
};

}  // namespace aerobreak
