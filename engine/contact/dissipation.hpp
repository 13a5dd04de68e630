#pragma once

namespace aerobreak {

// Energy taken out of (or, for stiffness_work, put into) the mechanical system by the contact
// laws, accumulated over a run. With the kinetic and stored energies it closes the balance:
// kinetic + stored + sum(dissipated) + van_der_waals_handover = initial + stiffness_work + external work.
struct DissipationTally {
  double damping = 0.0;   // normal viscous damping (eqs 8, 9)
  double friction = 0.0;  // Coulomb sliding of the Mindlin spring (eq 14)
  double rolling = 0.0;   // rolling-spring slip beyond xi_crit (eq 18)
  double twisting = 0.0;  // twisting-spring slip beyond its limit (eq 17)
  double breaking = 0.0;  // energy stored in a contact when it lets go (JKR hysteresis)
  // Work done on the tangential, rolling and twisting springs when their stiffness changes with
  // the contact radius at fixed stretch: these springs (eqs 11, 18) are not conservative.
  double stiffness_work = 0.0;
  // Van der Waals energy of pairs at the moment they come into contact (+) or leave it (-): the
  // long-range law hands the pair over to the contact law, whose adhesion replaces it.
  double van_der_waals_handover = 0.0;

  double dissipated() const { return damping + friction + rolling + twisting + breaking; }

  DissipationTally& operator+=(const DissipationTally& o) {
    damping += o.damping;
    friction += o.friction;
    rolling += o.rolling;
    twisting += o.twisting;
    breaking += o.breaking;
    stiffness_work += o.stiffness_work;
    van_der_waals_handover += o.van_der_waals_handover;
    return *this;
  }
};

}  // namespace aerobreak
