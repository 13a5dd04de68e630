#include "engine/growth/brownian_conditions.hpp"

#include <cmath>
#include <stdexcept>

#include "engine/dem/contact_forces.hpp"

namespace aerobreak {

ContactConstants primary_contact(const Material& material, const ContactModelSpec& model, double diameter,
                                 double mass) {
  ContactConstants c = sphere_pair_constants(0.5 * diameter, mass, 0.5 * diameter, mass, combine(material, material));
  make_contact_forces(model, model.normal)->complete(c);
  return c;
}

BrownianConditions brownian_conditions(const Material& material, const ContactModelSpec& model, double diameter,
                                       double mass, double bond_energy_over_kt, double persistence_length) {
  if (!(bond_energy_over_kt > 0.0)) throw std::invalid_argument("brownian conditions: bond_energy_over_kt must be > 0");
  if (!(persistence_length > 0.0)) throw std::invalid_argument("brownian conditions: persistence_length must be > 0");
  if (!(diameter > 0.0) || !(mass > 0.0))
    throw std::invalid_argument("brownian conditions: diameter and mass must be > 0");
  if (model.normal == NormalLaw::hertz)
    throw std::invalid_argument("brownian conditions: the Hertz law has no adhesion, so no bond to keep");

  const ContactConstants c = primary_contact(material, model, diameter, mass);
  const auto forces = make_contact_forces(model, model.normal);
  // Zero-load overlap of eqs 2-4: delta(a0) = a0^2/R* - (2/3) a0^2/R* = a0^2 / (3 R*).
  const double equilibrium = c.equilibrium_radius * c.equilibrium_radius / (3.0 * c.radius);

  BrownianConditions b;
  b.bond_energy = forces->normal_response(-c.break_overlap, c).energy - forces->normal_response(equilibrium, c).energy;
  b.temperature = b.bond_energy / bond_energy_over_kt;
  b.thermal_speed = std::sqrt(b.temperature / mass);
  b.drag = mass * b.thermal_speed / persistence_length;
  b.drag_per_diameter = b.drag / diameter;
  b.diffusion = b.temperature / b.drag;
  return b;
}

}  // namespace aerobreak
