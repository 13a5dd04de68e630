#include "engine/dem/contact_pool.hpp"

#include <stdexcept>

namespace aerobreak {

void ContactPool::grow() {
  history.resize(live_.size() + 1);
  if (per_slot_) constant_columns_.resize(live_.size() + 1);
  i_.push_back(0);
  j_.push_back(0);
  live_.push_back(0);
}

void ContactPool::store_constants(std::int32_t slot, const ContactConstants& constants) {
  if (!per_slot_) {
    if (!shared_) shared_ = constants;
    if (*shared_ == constants) return;
    // The first contact that differs: every slot gets its own copy from now on.
    per_slot_ = true;
    constant_columns_.resize(live_.size());
    for (std::size_t s = 0; s < live_.size(); ++s) constant_columns_.set(s, *shared_);
    shared_.reset();
  }
  constant_columns_.set(slot, constants);
}

void ContactPool::renumber(std::vector<std::int32_t>& references) {
  std::vector<std::int32_t> order;  // old slot of each new slot
  order.reserve(size());
  for (std::int32_t& slot : references) {
    if (slot < 0) continue;
    order.push_back(slot);
    slot = static_cast<std::int32_t>(order.size() - 1);
  }
  if (order.size() != size()) throw std::logic_error("ContactPool::renumber: a live contact is not referenced");
  history.permute(order);
  if (per_slot_) constant_columns_.permute(order);
  permute_column(i_, order);
  permute_column(j_, order);
  live_.assign(order.size(), 1);
  free_.clear();
}

}  // namespace aerobreak
