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
#include "engine/dem/contact_block.hpp"
#include "engine/dem/event_timing.hpp"

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
  double stored_energy(const ContactState& contact) const override {
    return model_.stored_energy(contact, contact.constants);
  }
  void release(const ContactState& contact, double overlap, double approach_rate, double dt,
               DissipationTally& tally) const override {
    model_.release(contact, overlap, approach_rate, dt, tally);
  }

  void add_pair_forces(Particles& p, PairList& pairs, const MaterialTable& materials, double dt, double formation_gap,
                       const std::vector<Pass>& passes) const override {
    add_pair_forces_in(OpenSpace{}, p, pairs, materials, dt, formation_gap, passes);
  }
  void add_periodic_pair_forces(Particles& p, PairList& pairs, const PeriodicBox& box, const MaterialTable& materials,
                                double dt, double formation_gap, const std::vector<Pass>& passes) const override {
    add_pair_forces_in(PeriodicSpace(box), p, pairs, materials, dt, formation_gap, passes);
  }

  void add_wall_forces(Particles& p, const Wall& wall, std::uint32_t wall_index, std::vector<std::int32_t>& slots,
                       const MaterialTable& materials, double dt, std::size_t begin, std::size_t end,
                       ContactLedger ledger) const override {
    const Vec3 into_wall = -wall.normal;
    // Carried on from the ledger's sums, not started afresh: ranges add up as one pass would.
    DissipationTally tally = ledger.tally;
    ContactLedger local{ledger.pool, tally, ledger.events, ledger.van_der_waals, ledger.drifted, ledger.timing_weight};
    double deepest = ledger.events.deepest_overlap_ratio;
    for (auto i = static_cast<std::uint32_t>(begin); i < end; ++i) {
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
        // The overlap grew by dt times the approach rate in the drift that made the contact.
        if (ledger.drifted)
          p.force[i] -=
              formation_timing(state.constants, overlap - dt * dot(p.velocity[i], into_wall), overlap, dt, local) *
              into_wall;
      }
      if (overlap < -ledger.pool.break_overlap(slot)) {
        p.force[i] -= close(slot, overlap, dot(p.velocity[i], into_wall), dt, local) * into_wall;
        continue;
      }
      ContactState state = ledger.pool.state(slot);
      const ContactMotion motion{
          into_wall, overlap, p.velocity[i], p.angular_velocity[i], Vec3{}, p.radius[i] - overlap, 0.0};
      const ContactLoad load = model_.evaluate(state, motion, dt, tally);
      ledger.pool.history.set(slot, state);
      deepest = std::max(deepest, overlap / state.constants.radius);
      p.force[i] += load.force_i;
      p.torque[i] += load.torque_i;
    }
    ledger.tally = tally;
    ledger.events.deepest_overlap_ratio = deepest;
  }

 private:
  // Where one pass over the pairs has got to: the rows before `row` are done, the particles
  // before `reported` reported complete; `tally` sums the pass's dissipation.
  struct Cursor {
    std::uint32_t row = 0;
    std::size_t reported = 0;
    DissipationTally tally;
  };

  // Each pass in turn takes as many rows as the one before allows (the first a stretch of
  // `stride` rows), until the last pass is through. One pass alone walks the rows straight on.
  template <class Space>
  [[gnu::always_inline]] void add_pair_forces_in(const Space& separation_of, Particles& p, PairList& pairs,
                                                 const MaterialTable& materials, double dt, double formation_gap,
                                                 const std::vector<Pass>& passes) const {
    const std::size_t depth = passes.size();
    const auto n = static_cast<std::uint32_t>(pairs.particles());
    std::vector<Cursor> cursors(depth);
    if (depth > 1) find_reach(pairs);
    for (std::size_t k = 0; k < depth;) {
      for (std::size_t pass = k; pass < depth; ++pass) {
        Cursor& c = cursors[pass];
        std::uint32_t end = n;
        if (pass == 0 && depth > 1)
          end = std::min<std::uint32_t>(n, c.row + stride);
        else if (pass > 0)
          end = rows_allowed(cursors[pass - 1].reported);
        if (end <= c.row) continue;
        take_rows(separation_of, p, pairs, materials, dt, formation_gap, passes[pass], c, end);
        if (c.row == n) passes[pass].ledger.tally += c.tally;
      }
      while (k < depth && cursors[k].row == n) ++k;
    }
  }

  // For each row, the farthest particle it or a row before it reaches: a pass can take the rows
  // whose reach the pass before has reported complete.
  void find_reach(const PairList& pairs) const {
    const std::size_t n = pairs.particles();
    reach_.resize(n);
    std::uint32_t farthest = 0;
    for (std::uint32_t row = 0; row < n; ++row) {
      // Rows are sorted by partner: the last is the farthest.
      const std::uint32_t first = pairs.row_start[row], last = pairs.row_start[row + 1];
      farthest = std::max({farthest, row, last > first ? pairs.neighbor[last - 1] : row});
      reach_[row] = farthest;
    }
  }
  std::uint32_t rows_allowed(std::size_t ready) const {
    return static_cast<std::uint32_t>(
        std::lower_bound(reach_.begin(), reach_.end(), static_cast<std::uint32_t>(ready)) - reach_.begin());
  }

  // Rows c.row .. end-1 of one pass, in blocks of ContactBlock::capacity live contacts:
  // (1) geometry and bookkeeping (contacts form and break), each live contact's motion written to
  // the block; (2) every law of every contact in the block, which the compiler evaluates several
  // contacts per vector instruction (the columns are contiguous and the laws straight-line code);
  // (3) the loads added to the particles in the order of the pairs, so that the sums, to the last
  // bit, do not depend on the skin, on when the list was rebuilt or on where a wavefront's pass
  // ends its stretch of rows: a contact that forms or lets go adds its timing force (and a release
  // its loss to the tally) at once, so the block is emptied before it; (4) the particles whose rows
  // are now all evaluated reported complete, at the latest when the last row is taken: the block
  // is then empty again for the next call, of this pass or another.
  // Separation vectors come from `separation_of` (OpenSpace or PeriodicSpace), which the compiler
  // inlines: the open-space instantiation is the plain loop.
  template <class Space>
  void take_rows(const Space& separation_of, Particles& p, PairList& pairs, const MaterialTable& materials, double dt,
                 double formation_gap, const Pass& pass, Cursor& c, std::uint32_t end) const {
    ContactBlock& block = block_;
    const Vec3* position = p.position.data();
    const Vec3* velocity = p.velocity.data();
    const Vec3* spin = p.angular_velocity.data();
    const double* radius = p.radius.data();
    ContactPool& pool = pass.ledger.pool;
    ContactLedger local{
        pool, c.tally, pass.ledger.events, pass.ledger.van_der_waals, pass.ledger.drifted, pass.ledger.timing_weight};
    const std::size_t n = pairs.particles();
    for (std::uint32_t i = c.row; i < end; ++i) {
      if (i - c.reported >= completion_run) report_before(i, p, dt, pass, block, c);
      prefetch_particle(p, std::min<std::size_t>(i + prefetch_distance, n - 1));
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
          slot = open_pair(p, materials, i, j, touching - std::sqrt(distance2), local);
          if (local.drifted) {
            empty_block(block, p, dt, local);  // (3): the loads of the pairs before this one first
            time_pair_formation(p, i, j, separation, slot, dt, local);
          }
        }
        const double distance = std::sqrt(distance2);
        const double overlap = touching - distance;
        const Vec3 normal = separation * (1.0 / distance);
        if (overlap < -pool.break_overlap(slot)) {
          empty_block(block, p, dt, local);  // (3), and the tally in the order of the pairs too
          const double timing = close(slot, overlap, dot(velocity[i] - velocity[j], normal), dt, local);
          p.force[i] -= timing * normal;
          p.force[j] += timing * normal;
          continue;
        }
        block.add(slot, i, j,
                  {normal, overlap, velocity[i] - velocity[j], spin[i], spin[j], radius_i - 0.5 * overlap,
                   radius[j] - 0.5 * overlap});
        if (block.full()) report_before(i, p, dt, pass, block, c);
      }
    }
    report_before(end, p, dt, pass, block, c);
    c.row = end;
  }

  // The block evaluated and its loads added before a contact event adds its own (take_rows' (3));
  // kept out of the pass's loop, where the laws' code would crowd the common path.
  [[gnu::noinline, gnu::cold]] void empty_block(ContactBlock& block, Particles& p, double dt,
                                                ContactLedger& ledger) const {
    finish_block(block, p, dt, ledger);
  }

  // Evaluates the block and reports the particles before `row` complete.
  void report_before(std::size_t row, Particles& p, double dt, const Pass& pass, ContactBlock& block, Cursor& c) const {
    ContactLedger local{pass.ledger.pool,    c.tally,
                        pass.ledger.events,  pass.ledger.van_der_waals,
                        pass.ledger.drifted, pass.ledger.timing_weight};
    finish_block(block, p, dt, local);
    pass.completed.complete(c.reported, row);
    c.reported = row;
  }

  // Rows the first pass of a wavefront takes at a time.
  static constexpr std::uint32_t stride = 128;

  // Longest run of particles reported complete at once, for sparse contacts (a full block
  // reports sooner): a few hundred particles' arrays fit in the nearest caches.
  static constexpr std::size_t completion_run = 256;

  // A cluster's pairs join particles close in index (BCCA and DLCA append whole clusters), so
  // the pass over the pairs walks the particles' arrays front to back; asking for those some
  // particles ahead, force and torque included (the block's last pass adds to them), keeps that
  // walk from waiting on memory once the arrays outgrow the caches (64,000 primaries: about
  // 10 % fewer nanoseconds per particle-step, measured; no change at 16,000).
  static constexpr std::size_t prefetch_distance = 48;
  static void prefetch_particle(const Particles& p, std::size_t i) {
    __builtin_prefetch(&p.position[i]);
    __builtin_prefetch(&p.velocity[i]);
    __builtin_prefetch(&p.angular_velocity[i]);
    __builtin_prefetch(&p.force[i], 1);
    __builtin_prefetch(&p.torque[i], 1);
  }

  void finish_block(ContactBlock& block, Particles& p, double dt, ContactLedger& ledger) const {
    ContactPool& pool = ledger.pool;
    const std::size_t size = block.size();
    if (size == 0) return;
    if (pool.shared_constants())
      evaluate_block(block, pool, SharedConstants{*pool.shared_constants()}, dt);
    else
      evaluate_block(block, pool, ColumnConstants{pool.constant_columns()}, dt);
    Vec3* force = p.force.data();
    Vec3* torque = p.torque.data();
    double deepest = ledger.events.deepest_overlap_ratio;
    for (std::size_t q = 0; q < size; ++q) {
      const ContactLoad load = block.motion.load(q);
      const std::uint32_t i = block.first[q], j = block.second[q];
      force[i] += load.force_i;
      force[j] -= load.force_i;
      torque[i] += load.torque_i;
      torque[j] += load.torque_j;
      ledger.tally += block.motion.dissipation(q);
      deepest = std::max(deepest, block.motion.overlap[q] / pool.reduced_radius(block.slot[q]));
    }
    ledger.events.deepest_overlap_ratio = deepest;
    block.clear();
  }

  // Where the laws read a contact's constants: one set shared by the whole pool ...
  struct SharedConstants {
    ContactConstants shared;
    [[gnu::always_inline]] ContactConstants get(std::size_t) const { return shared; }
    SharedConstants from(std::size_t) const { return *this; }
    SharedConstants copied(ContactBlock&, std::size_t, std::size_t) const { return *this; }
  };
  // ... or columns, from `offset` on.
  struct ColumnConstants {
    const ContactConstantColumns& columns;
    std::size_t offset = 0;
    [[gnu::always_inline]] ContactConstants get(std::size_t q) const { return columns.get(offset + q); }
    ColumnConstants from(std::size_t first) const { return {columns, first}; }
    // Rows begin .. end-1 of the block, past its last contact copies of that one.
    ColumnConstants copied(ContactBlock& block, std::size_t begin, std::size_t end) const {
      for (std::size_t q = begin; q < end; ++q)
        block.constants.set(q, columns.get(block.slot[std::min(q, block.size() - 1)]));
      return {block.constants, 0};
    }
  };

  // Contacts per vector of the widest vector unit a build may use (8 doubles, AVX-512): evaluated
  // in whole vectors, a block has no scalar remainder, which costs several lanes' time a contact.
  static constexpr std::size_t lanes = 8;

  // Slots follow the pairs since the last rebuild, so a block's contacts usually hold consecutive
  // slots: then the laws work on the pool's columns in place, in whole vectors. The rest of the
  // block (all of it if a contact formed or broke since) is evaluated on copies, padded to whole
  // vectors with copies of its last contact, whose results are dropped.
  template <class Constants>
  void evaluate_block(ContactBlock& block, ContactPool& pool, const Constants& constants, double dt) const {
    const std::size_t size = block.size();
    const std::size_t whole = size - size % lanes;
    const std::int32_t first_slot = block.slot[0];
    bool consecutive = true;
    for (std::size_t q = 1; q < size; ++q) consecutive = consecutive && block.slot[q] == first_slot + std::int32_t(q);
    if (consecutive) {
      const auto offset = static_cast<std::size_t>(first_slot);
      evaluate(pool.history, offset, constants.from(offset), block.motion, 0, whole, dt);
      if (whole == size) return;
    }
    const std::size_t begin = consecutive ? whole : 0;
    const std::size_t end = (size + lanes - 1) / lanes * lanes;
    for (std::size_t q = begin; q < size; ++q) block.history.set(q, pool.history.get(block.slot[q]));
    for (std::size_t q = size; q < end; ++q) {
      block.history.set(q, block.history.get(size - 1));
      block.motion.set(q, block.motion.get(size - 1));
    }
    evaluate(block.history, 0, constants.copied(block, begin, end), block.motion, begin, end, dt);
    for (std::size_t q = begin; q < size; ++q) pool.history.set(block.slot[q], block.history.get(q));
  }

  // The laws of the contacts begin .. end-1 of the block, whose history is at `offset` + q of
  // `history` and whose motion is at q of `motion`.
  template <class Constants>
  void evaluate(ContactHistoryColumns& history, std::size_t offset, const Constants& constants,
                ContactMotionColumns& motion, std::size_t begin, std::size_t end, double dt) const {
    // Every column is indexed by the contact alone: no iteration depends on another.
#pragma GCC ivdep
    for (std::size_t q = begin; q < end; ++q) {
      ContactHistory state = history.get(offset + q);
      DissipationTally tally;
      const ContactLoad load = model_.evaluate(state, constants.get(q), motion.get(q), dt, tally);
      history.set(offset + q, state);
      motion.set_result(q, load, tally);
    }
  }

  std::int32_t open_pair(const Particles& p, const MaterialTable& materials, std::uint32_t i, std::uint32_t j,
                         double overlap, ContactLedger& ledger) const {
    ContactState state;
    state.constants = sphere_pair_constants(p.radius[i], p.mass[i], p.radius[j], p.mass[j],
                                            materials.pair(p.material[i], p.material[j]));
    state.i = i;
    state.j = j;
    model_.open(state, overlap);
    ++ledger.events.made;
    hand_over(ledger, -overlap, state.constants.radius, +1.0);
    return ledger.pool.open(state);
  }

  // The energy still stored in a contact when it lets go is lost to the system (for JKR, the
  // work of the loading/unloading hysteresis). Returns the normal force that times the jump of
  // the normal force to zero to the crossing of the break overlap (event_timing.hpp).
  double close(std::int32_t& slot, double overlap, double approach_rate, double dt, ContactLedger& ledger) const {
    const ContactState state = ledger.pool.state(slot);
    const double timing = ledger.drifted ? ledger.timing_weight * release_timing(state, overlap) : 0.0;
    if (ledger.drifted) ledger.events.note_crossing(state.constants.break_overlap, state.overlap - overlap);
    model_.release(state, overlap, approach_rate, dt, ledger.tally);
    hand_over(ledger, -overlap, state.constants.radius, -1.0);
    ledger.pool.close(slot);
    slot = -1;
    ++ledger.events.broken;
    return timing;
  }

  // Timing of the jump from no force to F(0) where the overlap crossed 0, between the overlaps
  // `before` and `after` of the drift that made the contact, with its second-order part.
  double formation_timing(const ContactConstants& constants, double before, double after, double dt,
                          ContactLedger& ledger) const {
    const double jump = model_.normal.respond(0.0, constants).force;
    const double s = crossing_fraction(before, after, 0.0);
    ledger.events.note_crossing(constants.break_overlap, after - before);
    return ledger.timing_weight *
           (jump_timing_force(jump, s) + formation_lag_force(jump, s, after - before, constants.mass, dt));
  }

  // Timing of the jump from F(-delta_b) to no force where the overlap crossed -delta_b, between
  // the contact's last evaluated overlap and `overlap`.
  double release_timing(const ContactState& state, double overlap) const {
    const double threshold = -state.constants.break_overlap;
    const double jump = -model_.normal.respond(threshold, state.constants).force;
    return jump_timing_force(jump, crossing_fraction(state.overlap, overlap, threshold));
  }

  // A pair contact just made: its overlap a step before follows from the separation before the
  // drift, x_j - x_i - dt (v_j - v_i).
  void time_pair_formation(Particles& p, std::uint32_t i, std::uint32_t j, const Vec3& separation, std::int32_t slot,
                           double dt, ContactLedger& ledger) const {
    const double touching = p.radius[i] + p.radius[j];
    const double before = touching - norm(separation - dt * (p.velocity[j] - p.velocity[i]));
    const double after = touching - norm(separation);
    const Vec3 normal = separation * (1.0 / norm(separation));
    const double timing = formation_timing(ledger.pool.state(slot).constants, before, after, dt, ledger);
    p.force[i] -= timing * normal;
    p.force[j] += timing * normal;
  }

  // A pair entering contact leaves the van der Waals sum (sign +1); one leaving re-enters it (-1).
  static void hand_over(ContactLedger& ledger, double gap, double reduced_radius, double sign) {
    if (ledger.van_der_waals)
      ledger.tally.van_der_waals_handover += sign * ledger.van_der_waals->at_gap(gap, reduced_radius).energy;
  }

  Model model_;
  mutable ContactBlock block_;                // scratch of take_rows, kept to reuse its memory
  mutable std::vector<std::uint32_t> reach_;  // scratch of find_reach
};

using NormalChoice = std::variant<JkrNormal, DmtNormal, HertzNormal>;
using DampingChoice = std::variant<NoDamping, ViscoElasticDamping, TsujiDamping>;
using TangentialChoice = std::variant<NoTangential, MindlinTangential>;
using RollingChoice = std::variant<NoRolling, RollingResistance>;
using TwistingChoice = std::variant<NoTwisting, TwistingResistance>;

NormalChoice choose_normal(const ContactModelSpec& spec, NormalLaw law) {
  switch (law) {
    case NormalLaw::jkr:
      return JkrNormal{spec.separation};
    case NormalLaw::dmt:
      return DmtNormal{};
    case NormalLaw::hertz:
      return HertzNormal{};
  }
  return JkrNormal{spec.separation};
}

DampingChoice choose_damping(const ContactModelSpec& spec) {
  switch (spec.damping) {
    case DampingLaw::none:
      return NoDamping{};
    case DampingLaw::viscoelastic:
      return ViscoElasticDamping{spec.dissipative_time};
    case DampingLaw::tsuji:
      return TsujiDamping{tsuji_alpha(spec.restitution)};
  }
  return NoDamping{};
}

}  // namespace

double zero_load_overlap(const ContactForces& law, const ContactConstants& c) {
  if (law.normal_response(0.0, c).force >= 0.0) return 0.0;
  double low = 0.0, high = std::max(c.critical_overlap, 1e-9 * c.radius);
  for (int k = 0; k < 200 && law.normal_response(high, c).force <= 0.0; ++k) high *= 2.0;
  for (int k = 0; k < 200 && high - low > 1e-15 * high; ++k) {
    const double middle = 0.5 * (low + high);
    (law.normal_response(middle, c).force > 0.0 ? high : low) = middle;
  }
  return 0.5 * (low + high);
}

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
