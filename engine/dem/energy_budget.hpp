#pragma once
#include "engine/contact/dissipation.hpp"

namespace aerobreak {

// Where the energy of a run is at one instant. balance() is conserved by the dynamics up to the
// integration error: it is the quantity energy-conservation checks compare.
struct EnergyBudget {
  double translational_kinetic = 0.0;
  double rotational_kinetic = 0.0;
  double contact_elastic = 0.0;  // normal, tangential, rolling and twisting springs of live contacts
  double van_der_waals = 0.0;
  double gravitational = 0.0;
  DissipationTally dissipation;  // cumulative since the start of the run
  double external_work = 0.0;    // cumulative work of the Langevin forces

  double kinetic() const { return translational_kinetic + rotational_kinetic; }
  double mechanical() const { return kinetic() + contact_elastic + van_der_waals + gravitational; }
  double balance() const {
    return mechanical() + dissipation.dissipated() + dissipation.van_der_waals_handover - dissipation.stiffness_work -
           external_work;
  }
};

}  // namespace aerobreak
