#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "engine/dem/column_set.hpp"
#include "engine/contact/contact_constants.hpp"

namespace aerobreak {

// ContactConstants of every slot of a contact pool, one column per field: a loop over contacts
// reads them with plain vector loads (an array of the structs would need a gather per field,
// which stops the pair loop vectorising).
class ContactConstantColumns : public ColumnSet<ContactConstantColumns> {
 public:
  [[gnu::always_inline]] ContactConstants get(std::size_t s) const {
    ContactConstants c;
    c.radius = radius[s];
    c.mass = mass[s];
    c.modulus = modulus[s];
    c.shear = shear[s];
    c.work_of_adhesion = work_of_adhesion[s];
    c.hertz_coefficient = hertz_coefficient[s];
    c.equilibrium_radius = equilibrium_radius[s];
    c.pull_off_force = pull_off_force[s];
    c.critical_overlap = critical_overlap[s];
    c.break_overlap = break_overlap[s];
    c.overlap_scale = overlap_scale[s];
    return c;
  }
  void set(std::size_t s, const ContactConstants& c) {
    radius[s] = c.radius;
    mass[s] = c.mass;
    modulus[s] = c.modulus;
    shear[s] = c.shear;
    work_of_adhesion[s] = c.work_of_adhesion;
    hertz_coefficient[s] = c.hertz_coefficient;
    equilibrium_radius[s] = c.equilibrium_radius;
    pull_off_force[s] = c.pull_off_force;
    critical_overlap[s] = c.critical_overlap;
    break_overlap[s] = c.break_overlap;
    overlap_scale[s] = c.overlap_scale;
  }

  std::vector<double> radius, mass, modulus, shear, work_of_adhesion, hertz_coefficient, equilibrium_radius,
      pull_off_force, critical_overlap, break_overlap, overlap_scale;

 private:
  friend class ColumnSet<ContactConstantColumns>;
  std::vector<std::vector<double>*> columns() {
    return {&radius,
            &mass,
            &modulus,
            &shear,
            &work_of_adhesion,
            &hertz_coefficient,
            &equilibrium_radius,
            &pull_off_force,
            &critical_overlap,
            &break_overlap,
            &overlap_scale};
  }
};

}  // namespace aerobreak
