#pragma once
#include "engine/contact/normal_jkr.hpp"
#include "engine/contact/van_der_waals.hpp"

namespace aerobreak {

enum class NormalLaw { jkr, dmt, hertz };
enum class DampingLaw { none, viscoelastic, tsuji };

// The contact model of a run, as chosen by the user. It is turned into one compiled law
// combination (ContactModel) once, when the run starts.
struct ContactModelSpec {
  NormalLaw normal = NormalLaw::jkr;
  JkrSeparation separation = JkrSeparation::displacement;

  DampingLaw damping = DampingLaw::none;
  double dissipative_time = 0.0;  // A of the visco-elastic law (eq 8)
  double restitution = 1.0;       // target e of the Tsuji law (eq 9)

  bool tangential = true;  // Mindlin spring with Coulomb limit (eqs 10-14)
  double friction = 0.5;   // mu (eqs 10, 14, 17)

  bool rolling = false;           // rolling resistance (eq 18)
  double critical_rolling = 0.0;  // xi_crit
  bool twisting = false;          // twisting resistance (eq 17)

  bool van_der_waals = false;  // Hamaker attraction outside contact
  VanDerWaals hamaker;

  // Throws std::invalid_argument naming the offending field.
  void validate() const;
};

}  // namespace aerobreak
