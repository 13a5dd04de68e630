#include "engine/dem/contact_forces.hpp"

#include <algorithm>
#include <cmath>
#include <variant>

#include "engine/contact/contact_model.hpp"
#include "engine/contact/damping.hpp"
#include "engine/contact/normal_dmt.hpp"
#include "engine/contact/normal_hertz.hpp"
#include "engine/contact/normal_jkr.hpp"
#include "engine/contact/rolling_resistance.hpp"
#include "engine/contact/tangential_mindlin.hpp"
#include "engine/contact/twisting_resistance.hpp"
#include "engine/dem/contact_motion_columns.hpp"

namespace aerobreak {
namespace {

template <class Model>
class ContactForcesFor final : public ContactForces {
 public:
  explicit ContactForcesFor(Model model) : model_(model) {}

  void complete(ContactConstants& constants) const override { model_.normal.complete(constants); }
  NormalResponse normal_response(double overlap, const ContactConstants& constants) const override {
    return model_.normal.respond(overlap, constants);
  }

  void add_pair_forces(Particles& p, PairList& pairs, const MaterialTable& materials, double dt,
                       double formation_gap, ContactLedger ledger) const override {
    add_pair_forces_in(OpenSpace{}, p, pairs, materials, dt, formation_gap, ledger);
  }
  void add_periodic_pair_forces(Particles& p, PairList& pairs, const PeriodicBox& box, const MaterialTable& materials,
                                double dt, double formation_gap, ContactLedger ledger) const override {
    add_pair_forces_in(PeriodicSpace(box), p, pairs, materials, dt, formation_gap, ledger);
  }

  void add_wall_forces(Particles& p, const Wall& wall, std::uint32_t wall_index, std::vector<std::int32_t>& slots,
                       const MaterialTable& materials, double dt, ContactLedger ledger) const override {
    const std::size_t n = p.size();
    const Vec3 into_wall = -wall.normal;
    DissipationTally tally;
    ContactLedger local{ledger.pool, tally, ledger.events, ledger.van_der_waals};
    double deepest = ledger.events.deepest_overlap_ratio;
    for (std::uint32_t i = 0; i < n; ++i) {
      const double overlap = p.radius[i] - wall.gap(p.position[i]);
      std::int32_t& slot = slots[i];
      if (slot < 0) {
        if (overlap <= 0.0) continue;
        ContactState state;
        state.constants = sphere_wall_constants(p.radius[i], p.mass[i], materials.pair(p.material[i], wall.material));
        state.i = i;
        state.j = wall_index;
        state.with_wall = true;
        model_.open(state, overlap);
        slot = ledger.pool.open(state);
        ++ledger.events.made;
        hand_over(local, -overlap, state.constants.radius, +1.0);
      }
      if (overlap < -ledger.pool.constants(slot).break_overlap) {
        close(slot, overlap, dot(p.velocity[i], into_wall), dt, local);
        continue;
      }
      ContactState state = ledger.pool.state(slot);
      const ContactMotion motion{into_wall, overlap, p.velocity[i], p.angular_velocity[i], Vec3{},
                                 p.radius[i] - overlap, 0.0};
      const ContactLoad load = model_.evaluate(state, motion, dt, tally);
      ledger.pool.store(slot, state);
      deepest = std::max(deepest, overlap / state.constants.radius);
      p.force[i] += load.force_i;
      p.torque[i] += load.torque_i;
    }
    ledger.tally += tally;
    ledger.events.deepest_overlap_ratio = deepest;
  }

 private:
  // Three passes: (1) over the listed pairs, geometry and bookkeeping (contacts form and break),
  // the motion of each live contact written to its slot; (2) over all slots, every law of every
  // contact, which the compiler evaluates several contacts per vector instruction (the pool's
  // columns and the motion are contiguous in slot order, and the laws are straight-line code);
  // (3) over the pairs again, the loads of the live contacts added to the particles (a free
  // slot, evaluated in (2) on whatever its columns held, is never read).
  // Separation vectors come from `separation_of` (OpenSpace or PeriodicSpace), which the compiler
  // inlines: the open-space instantiation is the plain loop. Inlined into both callers, so that
  // each is compiled as the one loop it is.
  template <class Space>
  [[gnu::always_inline]] void add_pair_forces_in(const Space& separation_of, Particles& p, PairList& pairs,
                                                 const MaterialTable& materials, double dt, double formation_gap,
                                                 ContactLedger ledger) const {
    DissipationTally tally;
    ContactLedger local{ledger.pool, tally, ledger.events, ledger.van_der_waals};
    record_motion(separation_of, p, pairs, materials, dt, formation_gap, local);
    evaluate_slots(dt, ledger.pool);
    apply_loads(p, pairs, ledger.pool, local);
    ledger.tally += tally;
  }

  template <class Space>
  [[gnu::always_inline]] void record_motion(const Space& separation_of, const Particles& p, PairList& pairs,
                                            const MaterialTable& materials, double dt, double formation_gap,
                                            ContactLedger& ledger) const {
    const Vec3* position = p.position.data();
    const Vec3* velocity = p.velocity.data();
    const Vec3* spin = p.angular_velocity.data();
    const double* radius = p.radius.data();
    const std::size_t n = pairs.particles();
    for (std::uint32_t i = 0; i < n; ++i) {
      const Vec3 position_i = position[i];
      const double radius_i = radius[i];
      for (std::uint32_t k = pairs.row_start[i]; k < pairs.row_start[i + 1]; ++k) {
        const std::uint32_t j = pairs.neighbor[k];
        const Vec3 separation = separation_of(position[j] - position_i);
        const double distance2 = norm2(separation);
        const double touching = radius_i + radius[j];
        std::int32_t& slot = pairs.contact[k];
        if (slot < 0) {
          // A contact forms when the spheres overlap (delta > 0), or come within formation_gap.
          const double reach = touching + formation_gap;
          if (distance2 >= reach * reach) continue;
          slot = open_pair(p, materials, i, j, touching - std::sqrt(distance2), ledger);
          motion_.resize(ledger.pool.capacity());
        }
        const double distance = std::sqrt(distance2);
        const double overlap = touching - distance;
        const Vec3 normal = separation * (1.0 / distance);
        if (overlap < -ledger.pool.constants(slot).break_overlap) {
          close(slot, overlap, dot(velocity[i] - velocity[j], normal), dt, ledger);
          continue;
        }
        motion_.set(slot, {normal, overlap, velocity[i] - velocity[j], spin[i], spin[j], radius_i - 0.5 * overlap,
                           radius[j] - 0.5 * overlap});
      }
    }
  }

  void evaluate_slots(double dt, ContactPool& pool) const {
    const std::size_t slots = pool.capacity();
    motion_.resize(slots);
    const ContactConstantColumns& constants = pool.constant_columns;
    double* stretch_x = pool.stretch_x.data();
    double* stretch_y = pool.stretch_y.data();
    double* stretch_z = pool.stretch_z.data();
    double* rolling_x = pool.rolling_x.data();
    double* rolling_y = pool.rolling_y.data();
    double* rolling_z = pool.rolling_z.data();
    double* twist = pool.twist.data();
    double* contact_radius = pool.contact_radius.data();
    double* stored_energy = pool.stored_energy.data();
    double* overlap = pool.overlap.data();
    double* elastic_force = pool.elastic_force.data();
    double* damping_force = pool.damping_force.data();
    double* rolling_stiffness = pool.rolling_stiffness.data();
    ContactMotionColumns& m = motion_;
    // Every column is indexed by the slot alone: no iteration depends on another.
#pragma GCC ivdep
    for (std::size_t s = 0; s < slots; ++s) {
      const ContactConstants c = constants.get(s);
      ContactHistory state;
      state.tangential_stretch = {stretch_x[s], stretch_y[s], stretch_z[s]};
      state.rolling_displacement = {rolling_x[s], rolling_y[s], rolling_z[s]};
      state.twist_angle = twist[s];
      state.contact_radius = contact_radius[s];
      state.damping_force = damping_force[s];
      state.rolling_stiffness = rolling_stiffness[s];
      DissipationTally tally;
      const ContactLoad load = model_.evaluate(state, c, m.get(s), dt, tally);
      stretch_x[s] = state.tangential_stretch.x;
      stretch_y[s] = state.tangential_stretch.y;
      stretch_z[s] = state.tangential_stretch.z;
      rolling_x[s] = state.rolling_displacement.x;
      rolling_y[s] = state.rolling_displacement.y;
      rolling_z[s] = state.rolling_displacement.z;
      twist[s] = state.twist_angle;
      contact_radius[s] = state.contact_radius;
      stored_energy[s] = state.stored_energy;
      overlap[s] = state.overlap;
      elastic_force[s] = state.elastic_force;
      damping_force[s] = state.damping_force;
      rolling_stiffness[s] = state.rolling_stiffness;
      m.set_result(s, load, tally);
    }
  }

  // The loads of the live contacts added to their particles, their dissipation to the tally, in
  // the order of the pairs (not of the slots, which depends on when contacts formed and the list
  // was rebuilt): the sums, to the last bit, do not depend on the skin.
  void apply_loads(Particles& p, const PairList& pairs, const ContactPool& pool, ContactLedger& ledger) const {
    Vec3* force = p.force.data();
    Vec3* torque = p.torque.data();
    const double* reduced_radius = pool.constant_columns.radius.data();
    double deepest = ledger.events.deepest_overlap_ratio;
    const std::size_t n = pairs.particles();
    for (std::uint32_t i = 0; i < n; ++i)
      for (std::uint32_t k = pairs.row_start[i]; k < pairs.row_start[i + 1]; ++k) {
        const std::int32_t s = pairs.contact[k];
        if (s < 0) continue;
        const std::uint32_t j = pairs.neighbor[k];
        const ContactLoad load = motion_.load(s);
        force[i] += load.force_i;
        force[j] -= load.force_i;
        torque[i] += load.torque_i;
        torque[j] += load.torque_j;
        ledger.tally += motion_.dissipation(s);
        deepest = std::max(deepest, motion_.overlap[s] / reduced_radius[s]);
      }
    ledger.events.deepest_overlap_ratio = deepest;
  }

  std::int32_t open_pair(const Particles& p, const MaterialTable& materials, std::uint32_t i, std::uint32_t j,
                         double overlap, ContactLedger& ledger) const {
    ContactState state;
    state.constants =
        sphere_pair_constants(p.radius[i], p.mass[i], p.radius[j], p.mass[j], materials.pair(p.material[i], p.material[j]));
    state.i = i;
    state.j = j;
    model_.open(state, overlap);
    ++ledger.events.made;
    hand_over(ledger, -overlap, state.constants.radius, +1.0);
    return ledger.pool.open(state);
  }

  // The energy still stored in a contact when it lets go is lost to the system (for JKR, the
  // work of the loading/unloading hysteresis).
  static void close(std::int32_t& slot, double overlap, double approach_rate, double dt, ContactLedger& ledger) {
    const ContactState state = ledger.pool.state(slot);
    book_release(state, overlap, approach_rate, dt, ledger.tally);
    hand_over(ledger, -overlap, state.constants.radius, -1.0);
    ledger.pool.close(slot);
    slot = -1;
    ++ledger.events.broken;
  }

  // A pair entering contact leaves the van der Waals sum (sign +1); one leaving re-enters it (-1).
  static void hand_over(ContactLedger& ledger, double gap, double reduced_radius, double sign) {
    if (ledger.van_der_waals) ledger.tally.van_der_waals_handover += sign * ledger.van_der_waals->at_gap(gap, reduced_radius).energy;
  }

  Model model_;
  mutable ContactMotionColumns motion_;  // scratch of add_pair_forces, by pool slot, kept to reuse its memory
};

using NormalChoice = std::variant<JkrNormal, DmtNormal, HertzNormal>;
using DampingChoice = std::variant<NoDamping, ViscoElasticDamping, TsujiDamping>;
using TangentialChoice = std::variant<NoTangential, MindlinTangential>;
using RollingChoice = std::variant<NoRolling, RollingResistance>;
using TwistingChoice = std::variant<NoTwisting, TwistingResistance>;

NormalChoice choose_normal(const ContactModelSpec& spec, NormalLaw law) {
  switch (law) {
    case NormalLaw::jkr: return JkrNormal{spec.separation};
    case NormalLaw::dmt: return DmtNormal{};
    case NormalLaw::hertz: return HertzNormal{};
  }
  return JkrNormal{spec.separation};
}

DampingChoice choose_damping(const ContactModelSpec& spec) {
  switch (spec.damping) {
    case DampingLaw::none: return NoDamping{};
    case DampingLaw::viscoelastic: return ViscoElasticDamping{spec.dissipative_time};
    case DampingLaw::tsuji: return TsujiDamping{tsuji_alpha(spec.restitution)};
  }
  return NoDamping{};
}

}  // namespace

std::unique_ptr<ContactForces> make_contact_forces(const ContactModelSpec& spec, NormalLaw normal) {
  spec.validate();
  const TangentialChoice tangential =
      spec.tangential ? TangentialChoice{MindlinTangential{spec.friction}} : TangentialChoice{NoTangential{}};
  const RollingChoice rolling = spec.rolling && normal != NormalLaw::hertz
                                    ? RollingChoice{RollingResistance{spec.critical_rolling}}
                                    : RollingChoice{NoRolling{}};
  const TwistingChoice twisting =
      spec.twisting ? TwistingChoice{TwistingResistance{spec.friction}} : TwistingChoice{NoTwisting{}};
  return std::visit(
      [](auto n, auto d, auto t, auto r, auto w) -> std::unique_ptr<ContactForces> {
        using Model = ContactModel<decltype(n), decltype(d), decltype(t), decltype(r), decltype(w)>;
        return std::make_unique<ContactForcesFor<Model>>(Model{n, d, t, r, w});
      },
      choose_normal(spec, normal), choose_damping(spec), tangential, rolling, twisting);
}

}  // namespace aerobreak
