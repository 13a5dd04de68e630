#include "engine/core/units.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace aerobreak {

double normal_stiffness(const Material& m, double diameter) {
  return m.youngs_modulus * diameter / (3.0 * (1.0 - m.poisson_ratio * m.poisson_ratio));
}

double adhesion_energy_ratio(const Material& m, double diameter, double impact_speed) {
  const double pi = std::numbers::pi;
  const double nu2 = 1.0 - m.poisson_ratio * m.poisson_ratio;
  const double a0 = std::cbrt(9.0 * pi * m.surface_energy * nu2 * diameter * diameter / (8.0 * m.youngs_modulus));
  const double pull_off = 0.75 * pi * m.surface_energy * diameter;              // eq 5
  const double critical_overlap = 2.0 * a0 * a0 / (diameter * std::cbrt(6.0));  // eq 3
  const double mass = m.density * pi * diameter * diameter * diameter / 6.0;
  return 2.0 * pull_off * critical_overlap / (mass * impact_speed * impact_speed);  // eq 19
}

Material reduced_material(double gamma_over_kn, double poisson_ratio) {
  Material m;
  m.poisson_ratio = poisson_ratio;
  m.youngs_modulus = 3.0 * (1.0 - poisson_ratio * poisson_ratio);  // eq 7 with k_n = d = 1
  m.density = 6.0 / std::numbers::pi;
  m.surface_energy = gamma_over_kn;
  return m;
}

double PhysicalScaling::mass() const {
  return material.density * std::numbers::pi * diameter * diameter * diameter / 6.0;
}
double PhysicalScaling::stiffness() const { return normal_stiffness(material, diameter); }
double PhysicalScaling::time_unit() const { return std::sqrt(mass() / stiffness()); }
double PhysicalScaling::speed_unit() const { return diameter / time_unit(); }
double PhysicalScaling::energy_unit() const { return stiffness() * diameter * diameter; }
double PhysicalScaling::softened_time(double reduced) const { return reduced * time_unit() / std::sqrt(softening); }

Material PhysicalScaling::reduced() const {
  return reduced_material(material.surface_energy / stiffness(), material.poisson_ratio);
}

void PhysicalScaling::validate() const {
  material.validate("material");
  if (!(diameter > 0.0) || !std::isfinite(diameter)) throw std::invalid_argument("diameter must be > 0");
  if (!(softening > 0.0 && softening <= 1.0)) throw std::invalid_argument("softening must be in (0, 1]");
}

}  // namespace aerobreak
