#include "engine/dem/simulation.hpp"

#include "engine/contact/contact_model.hpp"
#include "engine/dem/simulation_force_pass.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>

namespace aerobreak {
namespace {

void validate_particles(const Particles& p, std::size_t material_count) {
  for (std::size_t i = 0; i < p.size(); ++i) {
    const std::string which = "particle " + std::to_string(i);
    if (!(p.radius[i] > 0.0) || !std::isfinite(p.radius[i]))
      throw std::invalid_argument(which + ": radius must be > 0");
    if (!(p.mass[i] > 0.0) || !std::isfinite(p.mass[i])) throw std::invalid_argument(which + ": mass must be > 0");
    if (p.material[i] >= material_count) throw std::invalid_argument(which + ": unknown material index");
    const Vec3& x = p.position[i];
    if (!std::isfinite(x.x) || !std::isfinite(x.y) || !std::isfinite(x.z))
      throw std::invalid_argument(which + ": position is not finite");
  }
}

// An adhesive normal law divides by the work of adhesion: every pair it meets needs w > 0.
void require_adhesion(const ContactModelSpec& spec, const MaterialTable& materials, const Particles& p,
                      const std::vector<Wall>& walls) {
  if (spec.normal == NormalLaw::hertz) return;
  std::set<std::uint16_t> present(p.material.begin(), p.material.end());
  auto check = [&](std::uint16_t a, std::uint16_t b, const std::string& what) {
    if (!(materials.pair(a, b).work_of_adhesion > 0.0))
      throw std::invalid_argument(what + ": the " + std::string(spec.normal == NormalLaw::jkr ? "JKR" : "DMT") +
                                  " law needs a positive surface energy; use the Hertz law without adhesion");
  };
  for (auto a : present)
    for (auto b : present) check(a, b, "materials " + std::to_string(a) + " and " + std::to_string(b));
  for (std::size_t w = 0; w < walls.size(); ++w)
    if (walls[w].adhesive)
      for (auto a : present) check(a, walls[w].material, "wall " + std::to_string(w) + " (adhesive)");
}

// A periodic box replaces the walls: a wall would cut through the images of the box. Gravity is
// refused too: its potential energy -m g.x is not periodic, so the energy ledger would jump at
// every wrap.
void validate_periodic(const SimulationSettings& settings, const std::vector<Wall>& walls) {
  if (!settings.periodic) return;
  settings.periodic->validate();
  if (!walls.empty()) throw std::invalid_argument("simulation: walls cannot be combined with a periodic box");
  if (norm2(settings.body.gravity) > 0.0)
    throw std::invalid_argument("simulation: gravity cannot be combined with a periodic box");
}

Wall normalised(Wall wall, std::size_t index, std::size_t material_count) {
  const double length = norm(wall.normal);
  const std::string which = "wall " + std::to_string(index);
  if (!(length > 0.0) || !std::isfinite(length)) throw std::invalid_argument(which + ": normal must be non-zero");
  if (wall.material >= material_count) throw std::invalid_argument(which + ": unknown material index");
  wall.normal = wall.normal / length;
  return wall;
}

}  // namespace

Simulation::Simulation(Particles particles, std::vector<Material> materials, std::vector<Wall> walls,
                       ContactModelSpec model, SimulationSettings settings)
    : particles_(std::move(particles)),
      materials_(std::move(materials)),
      spec_(model),
      settings_(settings),
      wavefront_({settings.wavefront_depth, settings.wavefront_min_particles, settings.wavefront_margin}) {
  validate_particles(particles_, materials_.size());
  if (!(settings_.initial_bond_gap >= 0.0)) throw std::invalid_argument("simulation: initial_bond_gap must be >= 0");
  for (std::size_t w = 0; w < walls.size(); ++w) walls_.push_back(normalised(walls[w], w, materials_.size()));
  validate_periodic(settings_, walls_);
  images_.assign(particles_.size(), ImageCount{});
  spec_.validate();
  require_adhesion(spec_, materials_, particles_, walls_);
  pair_forces_ = make_contact_forces(spec_, spec_.normal);
  for (const Wall& wall : walls_) {
    wall_forces_.push_back(make_contact_forces(spec_, wall.adhesive ? spec_.normal : NormalLaw::hertz));
    wall_slots_.emplace_back(particles_.size(), -1);
  }

  if (particles_.size() == 0 && !(settings_.time_step > 0.0))
    throw std::invalid_argument("simulation: no particles and no time step");
  // The automatic step at the speed scale; with a fixed step too, so that what depends on the
  // contact period (an impact's settle window) does not depend on how the step was chosen.
  if (!(settings_.time_step > 0.0)) {
    estimate_ = recommend_time_step(particles_, materials_, walls_, spec_, speed_scale(),
                                    {settings_.steps_per_period, settings_.steps_per_break_overlap});
  } else if (particles_.size() > 0) {
    try {
      estimate_ = recommend_time_step(particles_, materials_, walls_, spec_, speed_scale(),
                                      {settings_.steps_per_period, settings_.steps_per_break_overlap});
    } catch (const std::invalid_argument&) {
      estimate_ = TimeStepEstimate{};  // a fixed step needs none
    }
  }
  dt_ = settings_.time_step > 0.0 ? settings_.time_step : estimate_.time_step;
  limit_ = settings_.time_step > 0.0 ? TimeStepLimit::contact_period : estimate_.limit;
  history_.choices = settings_.time_step > 0.0 ? 0 : 1;

  // Automatic skin: a particle at the expected speed crosses half of it in about 20 steps of the
  // step at the speed scale, within [0.7, 1] smallest radius: a fractal cluster has few pairs per
  // particle, so a wide skin is cheap (measured: rebuilds cost more than the extra pairs down to 0.7 R).
  double skin = settings_.skin;
  if (skin <= 0.0 && particles_.size() > 0) {
    const double smallest = *std::min_element(particles_.radius.begin(), particles_.radius.end());
    skin = std::clamp(40.0 * speed_scale() * dt_, 0.7 * smallest, smallest);
  }
  std::unique_ptr<NeighborSearch> search;
  if (settings_.brute_force_neighbors)
    search = std::make_unique<BruteForceSearch>(settings_.periodic);
  else
    search = std::make_unique<CellListSearch>(settings_.periodic);
  const double margin = std::max(interaction_margin(), settings_.initial_bond_gap);
  if (settings_.periodic && particles_.size() > 0) {
    const double largest = *std::max_element(particles_.radius.begin(), particles_.radius.end());
    settings_.periodic->require_single_image(2.0 * largest + margin + skin);
  }
  neighbors_ = std::make_unique<VerletNeighborList>(std::move(search), margin, skin);
  rebuild_neighbors();
  start_step_chooser();
  next_dt_ = dt_;
  next_limit_ = limit_;
  set_half_steps(dt_, half_step_per_mass_, half_step_per_inertia_);
  particles_.clear_forces();
  compute_forces(false, settings_.initial_bond_gap, false);
}

// The step chosen from the speeds of the moment where there is an adhesion loop to resolve; the
// first choice, from the initial velocities, is the first step.
void Simulation::start_step_chooser() {
  if (!settings_.adaptive_time_step || settings_.time_step > 0.0 || !(settings_.steps_per_break_overlap > 0.0) ||
      settings_.body.langevin.enabled() || settings_.periodic)
    return;
  const BreakOverlaps overlaps = shortest_break_overlaps(particles_, materials_, walls_, spec_);
  if (!(overlaps.pair > 0.0) && !(overlaps.wall > 0.0)) return;
  chooser_ = std::make_unique<StepChooser>(estimate_.period / settings_.steps_per_period, overlaps,
                                           settings_.steps_per_break_overlap, settings_.step_headroom);
  const StepChooser::Choice choice =
      chooser_->choose(particles_, neighbors_->pairs(), walls_, neighbors_->built_at(), neighbors_->skin());
  dt_ = choice.time_step;
  limit_ = choice.limit;
  choice_expires_ = time_ + choice.hold;
}

void Simulation::set_half_steps(double dt, std::vector<double>& per_mass, std::vector<double>& per_inertia) const {
  per_mass.resize(particles_.size());
  per_inertia.resize(particles_.size());
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    per_mass[i] = 0.5 * dt / particles_.mass[i];
    per_inertia[i] = 0.5 * dt / particles_.inertia[i];
  }
}

double Simulation::speed_scale() const {
  if (settings_.speed_scale > 0.0) return settings_.speed_scale;
  double fastest = 0.0;
  for (std::size_t i = 0; i < particles_.size(); ++i)
    fastest =
        std::max(fastest, norm(particles_.velocity[i]) + norm(particles_.angular_velocity[i]) * particles_.radius[i]);
  // Gravity can accelerate a particle over the height of the system (plus one diameter).
  const double g = norm(settings_.body.gravity);
  if (g > 0.0) {
    Vec3 low = particles_.position[0], high = particles_.position[0];
    for (const Vec3& x : particles_.position) {
      low = {std::min(low.x, x.x), std::min(low.y, x.y), std::min(low.z, x.z)};
      high = {std::max(high.x, x.x), std::max(high.y, x.y), std::max(high.z, x.z)};
    }
    const double largest = *std::max_element(particles_.radius.begin(), particles_.radius.end());
    fastest += std::sqrt(2.0 * g * (norm(high - low) + 2.0 * largest));
  }
  const Langevin& l = settings_.body.langevin;
  if (l.enabled()) {
    const double lightest = *std::min_element(particles_.mass.begin(), particles_.mass.end());
    fastest += 4.0 * std::sqrt(3.0 * l.temperature / lightest);
  }
  return fastest;
}

// Pairs must be listed out to the farthest distance at which they can still interact: the JKR
// break-off overlap of the largest spheres (delta_c grows as R*^(1/3)) or the van der Waals cut-off.
double Simulation::interaction_margin() const {
  double margin = spec_.van_der_waals ? spec_.hamaker.cutoff : 0.0;
  if (particles_.size() == 0) return margin;
  const auto largest = std::max_element(particles_.radius.begin(), particles_.radius.end()) - particles_.radius.begin();
  std::set<std::uint16_t> present(particles_.material.begin(), particles_.material.end());
  for (auto a : present)
    for (auto b : present) {
      ContactConstants c =
          sphere_pair_constants(particles_.radius[largest], particles_.mass[largest], particles_.radius[largest],
                                particles_.mass[largest], materials_.pair(a, b));
      pair_forces_->complete(c);
      margin = std::max(margin, c.break_overlap);
    }
  return margin;
}

void Simulation::step() { run(1); }

// Velocity Verlet [S82]: v(n+1/2) = v(n) + dt F(n)/(2m), x(n+1) = x(n) + dt v(n+1/2), forces
// F(n+1) at x(n+1), v(n+1) = v(n+1/2) + dt F(n+1)/(2m); the same for the spin with the torque
// and the moment of inertia. Between calls the velocities are whole-step. Inside a run the closing
// half kick of one step and the opening half kick of the next are done together (verlet_step).
// Where the system is large enough, the wavefront runs several steps in one sweep over the data
// with the same result to the last bit (wavefront.hpp).
void Simulation::run(std::int64_t steps, double until) {
  if (steps <= 0 || !(time_ < until)) return;
  ParticleDrift drift = integrate<1>(0, particles_.size());  // the first step's opening half kick and drift
  commit_step();
  wavefront_.begin_run();
  for (std::int64_t done = 0; done < steps && time_ < until;) {
    if (const std::int64_t taken = wavefront_.advance(*this, drift, steps - done, until)) {
      done += taken;
      continue;
    }
    ++done;
    drift = verlet_step(drift, done < steps && time_ + dt_ < until);
  }
  kick();  // the last step's closing half kick
}

std::int64_t Simulation::steps_before(double until, std::int64_t most, bool& reaches) const {
  double clock = time_;
  for (std::int64_t k = 1; k <= most; ++k) {
    clock += dt_;
    if (!(clock < until)) {
      reaches = true;
      return k;
    }
  }
  reaches = false;
  return most;
}

// One step: the forces at the drifted positions (the neighbour list rebuilt first if a particle
// may have left its skin, and the step chosen again if the list was rebuilt or a velocity has
// departed from the one the step was chosen for by more than it allows); then, unless the run
// ends with this step, this step's closing half kick, the next step's opening half kick and its
// drift, particle by particle as the force pass completes each particle (ForcePass), with the
// force reset and the neighbour list's displacement check: the particles' arrays are streamed
// once per step. The two half kicks are two additions, rounded as two separate passes would round
// them; where the step changes, the closing one is of the old step and the opening one of the new.
ParticleDrift Simulation::verlet_step(ParticleDrift& drift, bool more) {
  prepare_forces(drift);
  advance_clock();
  const ParticleDrift next = compute_forces(false, 0.0, more);
  if (more) commit_step();
  return next;
}

// The drift just taken: the clock and the step history move on by its step.
void Simulation::advance_clock() {
  time_ += dt_;
  ++steps_;
  history_.record(dt_, limit_);
}

// Before a step's forces (and before its drift is added to the clock): the neighbour list rebuilt
// if a particle may have left its skin; the step chosen again at every rebuild (the new list may
// hold pairs the last choice did not see), whenever a drift velocity has departed from the last
// choice's by more than its budget, and when the last choice's hold has passed.
void Simulation::prepare_forces(ParticleDrift& drift) {
  bool rebuilt = false;
  if (drift.since_build2 > neighbors_->displacement_limit2()) {
    rebuild_neighbors();
    drift.since_build2 = 0.0;
    rebuilt = true;
  }
  if (chooser_ && (rebuilt || drift.departure2 > chooser_->budget2() || !(time_ < choice_expires_))) {
    choose_step();
    drift.departure2 = 0.0;
  }
}

// The next drift's step from the velocities of the last one (StepChooser); the half kick that
// opens it uses the new step, the one closing this step the old.
void Simulation::choose_step() {
  const StepChooser::Choice choice =
      chooser_->choose(particles_, neighbors_->pairs(), walls_, neighbors_->built_at(), neighbors_->skin(), next_dt_);
  ++history_.choices;
  choice_expires_ = time_ + choice.hold;
  next_limit_ = choice.limit;
  if (choice.time_step == dt_ && next_dt_ == dt_) return;
  next_dt_ = choice.time_step;
  set_half_steps(next_dt_, next_half_step_per_mass_, next_half_step_per_inertia_);
}

// The opening half kick and the drift of the next step have been taken: its step is the step.
void Simulation::commit_step() {
  limit_ = next_limit_;
  if (!switching_step()) return;
  dt_ = next_dt_;
  half_step_per_mass_.swap(next_half_step_per_mass_);
  half_step_per_inertia_.swap(next_half_step_per_inertia_);
}

void Simulation::ForcePass::complete(std::size_t begin, std::size_t end) {
  Simulation& s = sim_;
  for (std::size_t w = 0; w < s.walls_.size(); ++w) {
    const VanDerWaals* long_range = s.spec_.van_der_waals && s.walls_[w].adhesive ? &s.spec_.hamaker : nullptr;
    s.wall_forces_[w]->add_wall_forces(
        s.particles_, s.walls_[w], static_cast<std::uint32_t>(w), s.wall_slots_[w], s.materials_, s.dt_, begin, end,
        {s.wall_pool_, wall_tally_[w], s.wall_events_, long_range, step_ > 0, s.timing_weight()});
  }
  if (!finish_) return;
  add_body_forces(s.particles_, s.settings_.body, step_, s.dt_, begin, end, body_work_);
  if (integrate_) drift_.merge(s.integrate<2>(begin, end));
}

// `Kicks` half kicks of the particles begin .. end-1 with their current forces (two: the closing
// one of the step just computed and the opening one of the next; one: the opening one), a drift
// over the next step, and their forces cleared for the next evaluation; returns how far they have
// now moved since the neighbour list was built, and in this drift (the largest of each), and with
// `Watch` how far their drift velocities have departed from those the step was chosen for. Only
// while `Switching` (the next step differs from this one) does the opening kick read other half
// steps than the closing one.
template <int Kicks, bool Watch, bool Switching>
ParticleDrift Simulation::kick_and_drift(std::size_t begin, std::size_t end) {
  Particles& p = particles_;
  const std::vector<Vec3>& built_at = neighbors_->built_at();
  if (built_at.size() != p.size()) throw std::logic_error("simulation: neighbour list built for other particles");
  ParticleDrift drift;
  const double dt = next_dt_;
  const double* closing_mass = half_step_per_mass_.data();
  const double* closing_inertia = half_step_per_inertia_.data();
  const double* opening_mass = Switching ? next_half_step_per_mass_.data() : closing_mass;
  const double* opening_inertia = Switching ? next_half_step_per_inertia_.data() : closing_inertia;
  const Vec3* reference = Watch ? chooser_->reference().data() : nullptr;
  // Locals, not the arrays: the stores to one array would otherwise make the compiler read the
  // others again (they all hold doubles). The half steps too are read once into locals.
  for (std::size_t i = begin; i < end; ++i) {
    Vec3 velocity = p.velocity[i];
    Vec3 spin = p.angular_velocity[i];
    const Vec3 force = p.force[i];
    const Vec3 torque = p.torque[i];
    const double closing_m = closing_mass[i], closing_i = closing_inertia[i];
    const double opening_m = Switching ? opening_mass[i] : closing_m;
    const double opening_i = Switching ? opening_inertia[i] : closing_i;
    if constexpr (Kicks == 2) {
      velocity += closing_m * force;
      spin += closing_i * torque;
    }
    velocity += opening_m * force;
    spin += opening_i * torque;
    const Vec3 step = dt * velocity;
    const Vec3 position = p.position[i] + step;
    p.velocity[i] = velocity;
    p.angular_velocity[i] = spin;
    p.position[i] = position;
    p.force[i] = Vec3{};
    p.torque[i] = Vec3{};
    drift.since_build2 = std::max(drift.since_build2, norm2(position - built_at[i]));
    drift.last_step2 = std::max(drift.last_step2, norm2(step));
    if constexpr (Watch) drift.departure2 = std::max(drift.departure2, norm2(velocity - reference[i]));
  }
  return drift;
}

void Simulation::kick() {
  Particles& p = particles_;
  for (std::size_t i = 0; i < p.size(); ++i)
    half_kick(i, p.velocity[i], p.angular_velocity[i], p.force[i], p.torque[i], half_step_per_mass_.data(),
              half_step_per_inertia_.data());
}

// The forces at the current positions, which must have been cleared; with `integrate`, the
// particles then move on by a step (kick_and_drift<2>) and the return value says how far they
// have moved. Periodic or not is fixed for the run; each branch below calls a loop compiled for
// that case.
ParticleDrift Simulation::compute_forces(bool rebuild, double formation_gap, bool integrate) {
  if (rebuild) rebuild_neighbors();
  require_list_for_particles();
  // Van der Waals forces between listed pairs come after the walls', in a pass of their own:
  // then the body forces and the integration wait for it.
  const bool long_range_pass = spec_.van_der_waals;
  ForcePass pass(*this, !long_range_pass, integrate, steps_);
  const VanDerWaals* long_range = long_range_pass ? &spec_.hamaker : nullptr;
  // The first evaluation of a run (step 0) follows no drift: its contacts crossed nothing.
  add_pair_forces(formation_gap, {{{pair_pool_, tally_, pair_events_, long_range, steps_ > 0, timing_weight()}, pass}});
  pass.book(tally_, external_work_);
  if (!long_range_pass) return pass.drift();
  if (settings_.periodic)
    add_van_der_waals(PeriodicSpace(*settings_.periodic));
  else
    add_van_der_waals(OpenSpace{});
  double work = 0.0;
  add_body_forces(particles_, settings_.body, steps_, dt_, 0, particles_.size(), work);
  external_work_ += work;
  return integrate ? this->integrate<2>(0, particles_.size()) : ParticleDrift{};
}

// The pair loop over the listed pairs, compiled for open space or for the periodic box.
void Simulation::add_pair_forces(double formation_gap, const std::vector<ContactForces::Pass>& passes) {
  if (settings_.periodic)
    pair_forces_->add_periodic_pair_forces(particles_, neighbors_->pairs(), *settings_.periodic, materials_, dt_,
                                           formation_gap, passes);
  else
    pair_forces_->add_pair_forces(particles_, neighbors_->pairs(), materials_, dt_, formation_gap, passes);
}

void Simulation::rebuild_neighbors() {
  std::vector<std::int32_t> lost;
  // Wrapping only here keeps the positions continuous between builds, as the skin test needs.
  if (settings_.periodic) wrap_positions();
  neighbors_->rebuild(particles_, pair_pool_, lost);
  close_lost_contacts(lost);
  // The force loop then walks the contacts' columns in the order of the pairs, without holes.
  pair_pool_.renumber(neighbors_->pairs().contact);
}

// The pair loop reports the particles of its rows complete: the list must have a row for each.
void Simulation::require_list_for_particles() const {
  if (neighbors_->pairs().particles() != particles_.size())
    throw std::logic_error("simulation: neighbour list built for other particles");
}

void Simulation::wrap_positions() {
  for (std::size_t i = 0; i < particles_.size(); ++i)
    particles_.position[i] = settings_.periodic->wrap(particles_.position[i], images_[i]);
}

std::vector<Vec3> Simulation::unwrapped_positions() const {
  if (!settings_.periodic) return particles_.position;
  std::vector<Vec3> unwrapped(particles_.size());
  for (std::size_t i = 0; i < particles_.size(); ++i)
    unwrapped[i] = settings_.periodic->unwrap(particles_.position[i], images_[i]);
  return unwrapped;
}

Vec3 Simulation::separation(std::size_t i, std::size_t j) const {
  const Vec3 d = particles_.position[j] - particles_.position[i];
  return settings_.periodic ? settings_.periodic->minimum_image(d) : d;
}

void Simulation::close_lost_contacts(const std::vector<std::int32_t>& lost) {
  for (std::int32_t slot : lost) {
    const ContactState c = pair_pool_.state(slot);
    const Vec3 separation = this->separation(c.i, c.j);
    const double distance = norm(separation);
    const double gap = distance - particles_.radius[c.i] - particles_.radius[c.j];
    const double approach = dot(particles_.velocity[c.i] - particles_.velocity[c.j], separation) / distance;
    pair_forces_->release(c, -gap, approach, dt_, tally_);
    if (spec_.van_der_waals) tally_.van_der_waals_handover -= spec_.hamaker.at_gap(gap, c.constants.radius).energy;
    pair_pool_.close(slot);
    ++pair_events_.broken;
  }
}

template <class Space>
void Simulation::add_van_der_waals(const Space& separation_of) {
  const VanDerWaals& law = spec_.hamaker;
  Particles& p = particles_;
  const PairList& pairs = neighbors_->pairs();
  double energy = 0.0;
  for (std::uint32_t i = 0; i < pairs.particles(); ++i)
    for (std::uint32_t k = pairs.row_start[i]; k < pairs.row_start[i + 1]; ++k) {
      if (pairs.contact[k] >= 0) continue;
      const std::uint32_t j = pairs.neighbor[k];
      const Vec3 separation = separation_of(p.position[j] - p.position[i]);
      const double distance = norm(separation);
      const double reduced = p.radius[i] * p.radius[j] / (p.radius[i] + p.radius[j]);
      const auto r = law.at_gap(distance - p.radius[i] - p.radius[j], reduced);
      const Vec3 pull = (r.attraction / distance) * separation;
      p.force[i] += pull;
      p.force[j] -= pull;
      energy += r.energy;
    }
  for (std::size_t w = 0; w < walls_.size(); ++w) {
    if (!walls_[w].adhesive) continue;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (wall_slots_[w][i] >= 0) continue;
      const auto r = law.at_gap(walls_[w].gap(p.position[i]) - p.radius[i], p.radius[i]);
      p.force[i] -= r.attraction * walls_[w].normal;
      energy += r.energy;
    }
  }
  van_der_waals_energy_ = energy;
}

EnergyBudget Simulation::energy() const {
  EnergyBudget e;
  const Particles& p = particles_;
  for (std::size_t i = 0; i < p.size(); ++i) {
    e.translational_kinetic += 0.5 * p.mass[i] * norm2(p.velocity[i]);
    e.rotational_kinetic += 0.5 * p.inertia[i] * norm2(p.angular_velocity[i]);
  }
  // In the order of the pairs and of the walls, not of the pools' slots: the slot a contact gets
  // depends on when it formed relative to others, which a wavefront changes.
  const PairList& pairs = neighbors_->pairs();
  for (std::int32_t slot : pairs.contact)
    if (slot >= 0) e.contact_elastic += pair_forces_->stored_energy(pair_pool_.state(slot));
  for (std::size_t w = 0; w < walls_.size(); ++w)
    for (std::int32_t slot : wall_slots_[w])
      if (slot >= 0) e.contact_elastic += wall_forces_[w]->stored_energy(wall_pool_.state(slot));
  e.van_der_waals = van_der_waals_energy_;
  e.gravitational = gravitational_energy(p, settings_.body.gravity);
  e.dissipation = tally_;
  e.external_work = external_work_;
  return e;
}

Simulation::ContactReserve Simulation::contact_reserve(const ContactState& contact) const {
  const ContactForces& law = contact.with_wall ? *wall_forces_.at(contact.j) : *pair_forces_;
  const ContactConstants& c = contact.constants;
  if (last_rest_.law != &law || !(last_rest_.constants == c))
    last_rest_ = {&law, c, law.normal_response(zero_load_overlap(law, c), c).energy};
  const double rest = last_rest_.energy;
  return {law.stored_energy(contact) - rest, law.normal_response(-c.break_overlap, c).energy - rest};
}

double Simulation::wall_loop_energy(std::size_t i, std::size_t w) const {
  const ContactForces& law = *wall_forces_.at(w);
  const PairMaterial& material = materials_.pair(particles_.material[i], walls_[w].material);
  ContactConstants c = sphere_wall_constants(particles_.radius[i], particles_.mass[i], material);
  law.complete(c);
  return law.normal_response(-c.break_overlap, c).energy - law.normal_response(0.0, c).energy;
}

}  // namespace aerobreak
