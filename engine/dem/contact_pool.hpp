#pragma once
#include <cstdint>
#include <vector>

#include "engine/contact/contact_state.hpp"

namespace aerobreak {

// Storage of the live contacts. Slots are reused; a slot's index is stable while its contact
// lives, so neighbour lists and wall tables refer to contacts by index.
class ContactPool {
 public:
  std::int32_t open(const ContactState& state) {
    if (free_.empty()) {
      states_.push_back(state);
      live_.push_back(1);
      return static_cast<std::int32_t>(states_.size() - 1);
    }
    const std::int32_t slot = free_.back();
    free_.pop_back();
    states_[slot] = state;
    live_[slot] = 1;
    return slot;
  }
  void close(std::int32_t slot) {
    live_[slot] = 0;
    free_.push_back(slot);
  }

  ContactState& operator[](std::int32_t slot) { return states_[slot]; }
  const ContactState& operator[](std::int32_t slot) const { return states_[slot]; }
  bool live(std::size_t slot) const { return live_[slot] != 0; }
  std::size_t capacity() const { return states_.size(); }
  std::size_t size() const { return states_.size() - free_.size(); }

  template <class Visit>
  void for_each(Visit&& visit) const {
    for (std::size_t s = 0; s < states_.size(); ++s)
      if (live_[s]) visit(states_[s]);
  }

 private:
  std::vector<ContactState> states_;
  std::vector<std::uint8_t> live_;
  std::vector<std::int32_t> free_;
};

}  // namespace aerobreak
