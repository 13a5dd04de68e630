#pragma once
#include "engine/contact/contact_constants.hpp"
#include "engine/contact/model_spec.hpp"
#include "engine/core/material.hpp"

namespace aerobreak {

// Thermal conditions of Brownian (Langevin) cluster growth for primaries of one material and
// diameter d (reduced units: d = 1, m = 1, k_n = 1, core/units.hpp), chosen from two numbers:
//
// - the bond energy over kT, E_b / kT. E_b is the JKR work to pull a contact from its
//   equilibrium overlap delta_0 = a0^2 / (3 R*) (zero load, eqs 2-4) to where it lets go,
//   E_b = U(-delta_b) - U(delta_0), about 1.54 F_c delta_c for the displacement rule (eqs 3, 5).
//   Thermal breaking goes as exp(-E_b / kT) (Kramers 1940), so E_b / kT >> 1 makes every bond
//   permanent, as diffusion-limited aggregation assumes; a thermal collision has kinetic energy
//   ~kT, so the adhesion number of eq 19 is lambda ~ 2 F_c delta_c / kT >> 1 as well and every
//   collision sticks (Chokshi et al. 1993; Dominik & Tielens 1997).
// - the velocity persistence length of a free primary, l_p = v_th m / zeta with
//   v_th = sqrt(kT / m): the distance over which its velocity is remembered. l_p << d makes the
//   motion diffusive on the scale of the primaries (diffusion-limited, Meakin 1983; Kolb, Botet &
//   Jullien 1983); l_p >> cluster size would be ballistic aggregation instead (D_f ~ 1.9).
//   A free-draining cluster of n primaries has drag n zeta and mass n m, so its persistence
//   length is l_p / sqrt(n): clusters are more diffusive than primaries (Isella & Drossinos 2010,
//   Phys. Rev. E 82 011404, who find D ~ 1/n for such unshielded Langevin clusters).
//
// The Stokes-Einstein diffusion coefficient of a primary is D = kT / zeta = v_th l_p.
struct BrownianConditions {
  double bond_energy = 0.0;        // E_b, energy units (k_n d^2 in reduced units)
  double temperature = 0.0;        // kT
  double thermal_speed = 0.0;      // v_th = sqrt(kT / m) of one primary (per axis)
  double drag = 0.0;               // zeta of one primary
  double drag_per_diameter = 0.0;  // zeta / d, as Langevin takes it
  double diffusion = 0.0;          // D = kT / zeta of one primary
};

// Constants of a contact between two primaries of this material, diameter and mass, as the
// model's normal law fills them (a0, F_c, delta_c, break overlap).
ContactConstants primary_contact(const Material& material, const ContactModelSpec& model, double diameter, double mass);

// Throws std::invalid_argument for a non-positive ratio, length, diameter or mass, or a contact
// model without adhesion (Hertz: no bond to keep).
BrownianConditions brownian_conditions(const Material& material, const ContactModelSpec& model, double diameter,
                                       double mass, double bond_energy_over_kt, double persistence_length);

}  // namespace aerobreak
