#include "engine/dem/contact_pool.hpp"

namespace aerobreak {

void ContactPool::grow() {
  for (auto* column : {&stretch_x, &stretch_y, &stretch_z, &rolling_x, &rolling_y, &rolling_z, &twist, &contact_radius,
                       &stored_energy, &overlap, &elastic_force, &damping_force, &rolling_stiffness})
    column->push_back(0.0);
  constant_columns.resize(live_.size() + 1);
  i_.push_back(0);
  j_.push_back(0);
  live_.push_back(0);
}

template <class Column>
void ContactPool::permute(Column& column, const std::vector<std::int32_t>& order) {
  Column packed;
  packed.reserve(order.size());
  for (std::int32_t slot : order) packed.push_back(column[slot]);
  column = std::move(packed);
}

void ContactPool::renumber(std::vector<std::int32_t>& references) {
  std::vector<std::int32_t> order;  // old slot of each new slot
  order.reserve(size());
  for (std::int32_t& slot : references) {
    if (slot < 0) continue;
    order.push_back(slot);
    slot = static_cast<std::int32_t>(order.size() - 1);
  }
  for (auto* column : {&stretch_x, &stretch_y, &stretch_z, &rolling_x, &rolling_y, &rolling_z, &twist, &contact_radius,
                       &stored_energy, &overlap, &elastic_force, &damping_force, &rolling_stiffness})
    permute(*column, order);
  constant_columns.permute(order);
  permute(i_, order);
  permute(j_, order);
  live_.assign(order.size(), 1);
  free_.clear();
}

}  // namespace aerobreak
