#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "engine/dem/column_set.hpp"
#include "engine/contact/contact_state.hpp"

namespace aerobreak {

// ContactHistory of every slot, one column per field.
class ContactHistoryColumns : public ColumnSet<ContactHistoryColumns> {
 public:
  [[gnu::always_inline]] ContactHistory get(std::size_t s) const {
    ContactHistory h;
    h.tangential_stretch = {stretch_x[s], stretch_y[s], stretch_z[s]};
    h.rolling_displacement = {rolling_x[s], rolling_y[s], rolling_z[s]};
    h.twist_angle = twist[s];
    h.contact_radius = contact_radius[s];
    h.overlap = overlap[s];
    h.damping_force = damping_force[s];
    return h;
  }
  [[gnu::always_inline]] void set(std::size_t s, const ContactHistory& h) {
    stretch_x[s] = h.tangential_stretch.x;
    stretch_y[s] = h.tangential_stretch.y;
    stretch_z[s] = h.tangential_stretch.z;
    rolling_x[s] = h.rolling_displacement.x;
    rolling_y[s] = h.rolling_displacement.y;
    rolling_z[s] = h.rolling_displacement.z;
    twist[s] = h.twist_angle;
    contact_radius[s] = h.contact_radius;
    overlap[s] = h.overlap;
    damping_force[s] = h.damping_force;
  }

  std::vector<double> stretch_x, stretch_y, stretch_z;  // Mindlin spring (eqs 11-14)
  std::vector<double> rolling_x, rolling_y, rolling_z;  // xi (eq 18)
  std::vector<double> twist;                            // phi (eq 17)
  std::vector<double> contact_radius, overlap, damping_force;

 private:
  friend class ColumnSet<ContactHistoryColumns>;
  std::vector<std::vector<double>*> columns() {
    return {&stretch_x, &stretch_y, &stretch_z,      &rolling_x, &rolling_y,
            &rolling_z, &twist,     &contact_radius, &overlap,   &damping_force};
  }
};

}  // namespace aerobreak
