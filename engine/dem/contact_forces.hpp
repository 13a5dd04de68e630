#pragma once
#include <cstddef>
#include <algorithm>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "engine/contact/dissipation.hpp"
#include "engine/contact/model_spec.hpp"
#include "engine/core/material_table.hpp"
#include "engine/core/particles.hpp"
#include "engine/dem/contact_pool.hpp"
#include "engine/dem/wall.hpp"
#include "engine/neighbor/pair_list.hpp"
#include "engine/neighbor/periodic_box.hpp"

namespace aerobreak {

struct ContactEvents {
  std::uint64_t made = 0;
  std::uint64_t broken = 0;
  // Deepest overlap seen, over R*: Hertz and JKR theory assume small strains (delta << R*).
  double deepest_overlap_ratio = 0.0;
  // The fewest steps in which a contact that formed or let go would have crossed its break
  // overlap delta_b at the speed it had then: delta_b over the overlap's change in the drift of
  // the event (docs/MODEL.md 9.2 asks for steps_per_break_overlap); infinite while no contact with
  // a tensile range has formed or let go.
  double fewest_steps_per_break_overlap = std::numeric_limits<double>::infinity();
  void note_crossing(double break_overlap, double travel) {
    if (break_overlap > 0.0 && travel > 0.0)
      fewest_steps_per_break_overlap = std::min(fewest_steps_per_break_overlap, break_overlap / travel);
  }
};

// What one force pass reads and writes besides the particles.
struct ContactLedger {
  ContactPool& pool;
  DissipationTally& tally;
  ContactEvents& events;
  const VanDerWaals* van_der_waals = nullptr;  // set when the long-range law is on for these contacts
  // The positions have just drifted by a step (false at a run's first evaluation): a contact that
  // forms or lets go crossed its threshold during that drift, and its force jump is timed to the
  // crossing (event_timing.hpp).
  bool drifted = true;
  // Where the step changes after this force pass, its force acts for (dt + dt_next) / 2 instead
  // of dt: the forces that time a jump (event_timing.hpp), meant as an impulse over dt, are
  // weighted by 2 dt / (dt + dt_next).
  double timing_weight = 1.0;
};

// Told by the pair loop which particles have received all their pair forces of the pass. The list
// is a half list (particle i's partners j > i are in row i), so particle i has them once row i's
// contacts are evaluated; the pair loop reports them in runs of at most a few hundred, so that
// what comes next for those particles (walls, body forces, integration) finds their arrays still
// in the nearest caches.
class ParticleCompletion {
 public:
  virtual void complete(std::size_t begin, std::size_t end) = 0;

 protected:
  ~ParticleCompletion() = default;
};

// The contact force loops of one compiled law combination. Chosen once per run by
// make_contact_forces; the loops themselves contain no model switches.
class ContactForces {
 public:
  virtual ~ContactForces() = default;

  // What one force pass over the pairs writes to: its ledger, and whom it tells that a particle
  // has all its pair forces.
  struct Pass {
    ContactLedger ledger;
    ParticleCompletion& completed;
  };
  // Particle-particle contacts: forms, evaluates and breaks the contacts of every listed pair.
  // A contact forms where the surfaces are closer than formation_gap (0: where they touch).
  // Every particle is reported to each pass's `completed` once, in index order, after its last
  // pair force of that pass. One pass is one step's forces. Several are those of consecutive
  // steps, run together as a wavefront: pass k takes a row once pass k-1 has reported complete
  // (and so moved on) the row's particle and all its partners, so that each particle's arrays are
  // used by all passes while they are still in the caches. Each pass gives exactly what it would
  // alone; the list must hold for the positions of every pass, which the caller checks afterwards.
  virtual void add_pair_forces(Particles& particles, PairList& pairs, const MaterialTable& materials, double dt,
                               double formation_gap, const std::vector<Pass>& passes) const = 0;
  // The same in a periodic box: each pair interacts through its nearest images. A separate
  // compiled loop, so that the open-space loop above carries no periodic test.
  virtual void add_periodic_pair_forces(Particles& particles, PairList& pairs, const PeriodicBox& box,
                                        const MaterialTable& materials, double dt, double formation_gap,
                                        const std::vector<Pass>& passes) const = 0;
  // Contacts of the particles begin .. end-1 with one wall; slots[i] is particle i's contact with
  // it, or -1. The dissipation is added to ledger.tally in particle order, so that a pass in
  // several ranges sums exactly as one over all particles.
  virtual void add_wall_forces(Particles& particles, const Wall& wall, std::uint32_t wall_index,
                               std::vector<std::int32_t>& slots, const MaterialTable& materials, double dt,
                               std::size_t begin, std::size_t end, ContactLedger ledger) const = 0;
  // Adhesion constants the normal law gives a contact with these effective properties.
  virtual void complete(ContactConstants& constants) const = 0;
  // The normal law's response at this overlap (for time-step estimates and diagnostics).
  virtual NormalResponse normal_response(double overlap, const ContactConstants& constants) const = 0;
  // Elastic energy the springs of a live contact store (ContactModel::stored_energy).
  virtual double stored_energy(const ContactState& contact) const = 0;
  // Books the energy a contact takes with it when it lets go at `overlap` (ContactModel::release).
  virtual void release(const ContactState& contact, double overlap, double approach_rate, double dt,
                       DissipationTally& tally) const = 0;
};

// `normal` overrides spec.normal (walls without adhesion use Hertz with the particles' other laws).
std::unique_ptr<ContactForces> make_contact_forces(const ContactModelSpec& spec, NormalLaw normal);

// The overlap at which the elastic force of `law` vanishes for the completed constants `c`, by
// bisection on the stable branch (0 for a law without adhesion, whose force vanishes at touching).
double zero_load_overlap(const ContactForces& law, const ContactConstants& c);

}  // namespace aerobreak
