#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "engine/dem/contact_constant_columns.hpp"
#include "engine/dem/contact_history_columns.hpp"
#include "engine/dem/contact_motion_columns.hpp"

namespace aerobreak {

// A block of live contacts on their way through the pair loop: their slots, particles and
// motion, the loads and dissipation the laws answer with, and room for copies of their history
// and constants when their slots are not consecutive; one column per field, small enough to stay
// in the processor's nearest caches between the pass that fills it and the passes that use it
// (a scratch for all 64,000 contacts of a large cluster would not, and the loop would wait on
// memory).
class ContactBlock {
 public:
  static constexpr std::size_t capacity = 128;

  ContactBlock() {
    slot.resize(capacity);
    first.resize(capacity);
    second.resize(capacity);
    constants.resize(capacity);
    history.resize(capacity);
    motion.resize(capacity);
  }

  std::size_t size() const { return size_; }
  bool full() const { return size_ == capacity; }
  void clear() { size_ = 0; }

  void add(std::int32_t s, std::uint32_t i, std::uint32_t j, const ContactMotion& m) {
    slot[size_] = s;
    first[size_] = i;
    second[size_] = j;
    motion.set(size_, m);
    ++size_;
  }

  std::vector<std::int32_t> slot;
  std::vector<std::uint32_t> first, second;  // the particles i and j
  ContactConstantColumns constants;
  ContactHistoryColumns history;
  ContactMotionColumns motion;

 private:
  std::size_t size_ = 0;
};

}  // namespace aerobreak
