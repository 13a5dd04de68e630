#include "engine/contact/model_spec.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace aerobreak {

void ContactModelSpec::validate() const {
  auto require = [](bool ok, const std::string& message) {
    if (!ok) throw std::invalid_argument("contact model: " + message);
  };
  require(std::isfinite(dissipative_time) && dissipative_time >= 0.0, "dissipative_time must be >= 0");
  require(damping != DampingLaw::tsuji || (restitution > 0.0 && restitution <= 1.0),
          "restitution must be in (0, 1] for Tsuji damping");
  require(std::isfinite(friction) && friction >= 0.0, "friction must be >= 0");
  require(!rolling || (std::isfinite(critical_rolling) && critical_rolling > 0.0),
          "critical_rolling (xi_crit) must be > 0 when rolling resistance is on");
  require(!rolling || normal != NormalLaw::hertz,
          "rolling resistance needs an adhesive normal law (k_r = 4 F_c (a/a0)^(3/2), eq 18)");
  if (van_der_waals) {
    require(std::isfinite(hamaker.hamaker) && hamaker.hamaker > 0.0, "hamaker constant must be > 0");
    require(hamaker.min_separation > 0.0, "min_separation (z0) must be > 0");
    require(hamaker.cutoff > hamaker.min_separation, "van der Waals cutoff must exceed z0");
  }
}

}  // namespace aerobreak
