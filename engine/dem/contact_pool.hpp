#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include "engine/contact/contact_state.hpp"
#include "engine/dem/contact_constant_columns.hpp"
#include "engine/dem/contact_history_columns.hpp"

namespace aerobreak {

// Storage of the live contacts of one kind (particle-particle or particle-wall), one column per
// field of ContactState (structure of arrays), so that the pair force loop, which meets the
// contacts in slot order, streams just the columns it needs. Slots are reused; a slot's index is
// stable while its contact lives (neighbour lists and wall tables refer to contacts by slot)
// until renumber() packs the live contacts into the order the caller gives.
// Constants are kept once for the whole pool while every contact it has held had the same ones
// (spheres of one radius and one material, as in a monodisperse cluster), so that the pair loop
// reads them as scalars instead of streaming eleven columns; per slot from the first contact
// that differs.
class ContactPool {
 public:
  explicit ContactPool(bool with_wall) : with_wall_(with_wall) {}

  std::int32_t open(const ContactState& state) {
    std::int32_t slot;
    if (free_.empty()) {
      slot = static_cast<std::int32_t>(live_.size());
      grow();
    } else {
      slot = free_.back();
      free_.pop_back();
    }
    history.set(slot, state);
    i_[slot] = state.i;
    j_[slot] = state.j;
    store_constants(slot, state.constants);
    live_[slot] = 1;
    return slot;
  }
  void close(std::int32_t slot) {
    live_[slot] = 0;
    free_.push_back(slot);
  }

  // The contact in one piece (a copy).
  ContactState state(std::int32_t slot) const {
    ContactState s;
    static_cast<ContactHistory&>(s) = history.get(slot);
    s.constants = constants(slot);
    s.i = i_[slot];
    s.j = j_[slot];
    s.with_wall = with_wall_;
    return s;
  }
  ContactConstants constants(std::size_t slot) const { return shared_ ? *shared_ : constant_columns_.get(slot); }
  double break_overlap(std::size_t slot) const {
    return shared_ ? shared_->break_overlap : constant_columns_.break_overlap[slot];
  }
  double reduced_radius(std::size_t slot) const { return shared_ ? shared_->radius : constant_columns_.radius[slot]; }
  // The constants of every contact, while they are shared (else empty) ...
  const std::optional<ContactConstants>& shared_constants() const { return shared_; }
  // ... or else per slot.
  const ContactConstantColumns& constant_columns() const { return constant_columns_; }

  std::uint32_t i(std::size_t slot) const { return i_[slot]; }
  std::uint32_t j(std::size_t slot) const { return j_[slot]; }
  bool live(std::size_t slot) const { return live_[slot] != 0; }
  std::size_t capacity() const { return live_.size(); }
  std::size_t size() const { return live_.size() - free_.size(); }

  // Packs the live contacts into slots 0 .. size()-1 in the order in which `references` names
  // them, and rewrites `references` (slots, -1 for none) to match. Every live contact must be
  // named exactly once: the pair force loop then meets the contacts in the neighbour list's
  // order, without holes.
  void renumber(std::vector<std::int32_t>& references);

  template <class Visit>
  void for_each(Visit&& visit) const {
    for (std::size_t s = 0; s < live_.size(); ++s)
      if (live_[s]) visit(state(static_cast<std::int32_t>(s)));
  }

  ContactHistoryColumns history;

 private:
  void grow();
  void store_constants(std::int32_t slot, const ContactConstants& constants);

  bool with_wall_;
  std::vector<std::uint32_t> i_, j_;
  std::vector<std::uint8_t> live_;
  std::vector<std::int32_t> free_;
  std::optional<ContactConstants> shared_;
  bool per_slot_ = false;  // constants differ between contacts: kept in constant_columns_
  ContactConstantColumns constant_columns_;
};

// Every live contact of a run, particle-particle and particle-wall.
class ContactsView {
 public:
  ContactsView(const ContactPool& pairs, const ContactPool& walls) : pairs_(pairs), walls_(walls) {}
  std::size_t size() const { return pairs_.size() + walls_.size(); }
  template <class Visit>
  void for_each(Visit&& visit) const {
    pairs_.for_each(visit);
    walls_.for_each(visit);
  }

 private:
  const ContactPool& pairs_;
  const ContactPool& walls_;
};

}  // namespace aerobreak
