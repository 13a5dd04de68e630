#pragma once
#include <cstddef>
#include <vector>

#include "engine/contact/contact_model.hpp"
#include "engine/dem/column_set.hpp"

namespace aerobreak {

// The motion of a block of contacts at this step and the load and dissipation their laws answer
// with, one column per component: the pair loop's hand-over between its scalar bookkeeping pass,
// its vectorised evaluation pass and the pass that adds the loads up (dem/contact_forces.cpp).
class ContactMotionColumns : public ColumnSet<ContactMotionColumns> {
 public:
  [[gnu::always_inline]] void set(std::size_t s, const ContactMotion& m) {
    normal_x[s] = m.normal.x;
    normal_y[s] = m.normal.y;
    normal_z[s] = m.normal.z;
    overlap[s] = m.overlap;
    velocity_x[s] = m.velocity.x;
    velocity_y[s] = m.velocity.y;
    velocity_z[s] = m.velocity.z;
    spin_i_x[s] = m.spin_i.x;
    spin_i_y[s] = m.spin_i.y;
    spin_i_z[s] = m.spin_i.z;
    spin_j_x[s] = m.spin_j.x;
    spin_j_y[s] = m.spin_j.y;
    spin_j_z[s] = m.spin_j.z;
    lever_i[s] = m.lever_i;
    lever_j[s] = m.lever_j;
  }
  [[gnu::always_inline]] ContactMotion get(std::size_t s) const {
    return {{normal_x[s], normal_y[s], normal_z[s]},
            overlap[s],
            {velocity_x[s], velocity_y[s], velocity_z[s]},
            {spin_i_x[s], spin_i_y[s], spin_i_z[s]},
            {spin_j_x[s], spin_j_y[s], spin_j_z[s]},
            lever_i[s],
            lever_j[s]};
  }

  [[gnu::always_inline]] void set_result(std::size_t s, const ContactLoad& l, const DissipationTally& t) {
    damping[s] = t.damping;
    friction[s] = t.friction;
    rolling[s] = t.rolling;
    twisting[s] = t.twisting;
    stiffness_work[s] = t.stiffness_work;
    force_x[s] = l.force_i.x;
    force_y[s] = l.force_i.y;
    force_z[s] = l.force_i.z;
    torque_i_x[s] = l.torque_i.x;
    torque_i_y[s] = l.torque_i.y;
    torque_i_z[s] = l.torque_i.z;
    torque_j_x[s] = l.torque_j.x;
    torque_j_y[s] = l.torque_j.y;
    torque_j_z[s] = l.torque_j.z;
  }
  DissipationTally dissipation(std::size_t s) const {
    DissipationTally t;
    t.damping = damping[s];
    t.friction = friction[s];
    t.rolling = rolling[s];
    t.twisting = twisting[s];
    t.stiffness_work = stiffness_work[s];
    return t;
  }
  [[gnu::always_inline]] ContactLoad load(std::size_t s) const {
    return {{force_x[s], force_y[s], force_z[s]},
            {torque_i_x[s], torque_i_y[s], torque_i_z[s]},
            {torque_j_x[s], torque_j_y[s], torque_j_z[s]}};
  }

  std::vector<double> normal_x, normal_y, normal_z, overlap;

 private:
  friend class ColumnSet<ContactMotionColumns>;
  std::vector<std::vector<double>*> columns() {
    return {&normal_x, &normal_y, &normal_z,   &overlap,    &velocity_x,    &velocity_y, &velocity_z, &spin_i_x,
            &spin_i_y, &spin_i_z, &spin_j_x,   &spin_j_y,   &spin_j_z,      &lever_i,    &lever_j,    &force_x,
            &force_y,  &force_z,  &torque_i_x, &torque_i_y, &torque_i_z,    &torque_j_x, &torque_j_y, &torque_j_z,
            &damping,  &friction, &rolling,    &twisting,   &stiffness_work};
  }

  std::vector<double> velocity_x, velocity_y, velocity_z;  // v_i - v_j
  std::vector<double> spin_i_x, spin_i_y, spin_i_z, spin_j_x, spin_j_y, spin_j_z;
  std::vector<double> lever_i, lever_j;
  std::vector<double> force_x, force_y, force_z;  // on i; j receives the opposite
  std::vector<double> torque_i_x, torque_i_y, torque_i_z, torque_j_x, torque_j_y, torque_j_z;
  std::vector<double> damping, friction, rolling, twisting, stiffness_work;  // this step's dissipation
};

}  // namespace aerobreak
