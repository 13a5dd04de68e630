#pragma once
#include <cstddef>
#include <optional>

#include "engine/contact/contact_constants.hpp"
#include "engine/contact/model_spec.hpp"
#include "engine/core/material_table.hpp"
#include "engine/core/particles.hpp"
#include "engine/dem/contact_forces.hpp"
#include "engine/dem/wall.hpp"

namespace aerobreak {

// Energy scales of one contact (docs/MODEL.md 1.3): the contact the normal law gives two
// primaries of the same radius.
struct ContactEnergies {
  double pull_off_force = 0.0;       // F_c (eq 5; the DMT analogue; 0 for Hertz)
  double critical_overlap = 0.0;     // delta_c (eq 3; 0 without adhesion)
  double equilibrium_overlap = 0.0;  // where the elastic force vanishes (zero load)
  double break_overlap = 0.0;        // the contact lets go at -break_overlap
  // E_break: the work that takes the contact from its zero-load equilibrium to where it lets go,
  // U(-break_overlap) - U(equilibrium_overlap): 1.5426 F_c delta_c for JKR with the displacement
  // rule (Chokshi et al. 1993; Dominik & Tielens 1997), 1.0691 F_c delta_c with the force rule.
  double breaking_energy = 0.0;
  // E_roll = 6 pi^2 gamma R* xi_crit (Dominik & Tielens 1997), gamma = w/2 the surface energy of
  // one surface: the energy to roll one contact through 90 degrees. NaN without rolling resistance.
  double rolling_energy = 0.0;
};

// The energies of the contact `constants` (geometry and material, not yet completed by the law)
// under `law`; `critical_rolling` is xi_crit, 0 without rolling resistance.
ContactEnergies contact_energies(const ContactForces& law, ContactConstants constants, double critical_rolling);

// The dimensionless energy groups of an impact (docs/MODEL.md 1.3): the impact's kinetic energy
// per initial contact over E_break, E_kin / (N_c E_break), and over the rolling energy,
// E_kin / E_roll. NaN where undefined (no initial contact, no adhesion, no rolling resistance).
struct EnergyGroups {
  double energy_per_contact = 0.0;
  double energy_over_rolling = 0.0;
};
EnergyGroups energy_groups(double impact_kinetic_energy, std::size_t initial_contacts, const ContactEnergies& energies);

// The small-strain range of the contact laws (docs/MODEL.md 3.7): overlap and contact radius over
// the radius of the primary.
struct StrainLimits {
  double overlap_ratio = 0.5;
  double contact_radius_ratio = 0.5;
};

struct StrainMeasure {
  double overlap_ratio = 0.0;         // deepest overlap / primary radius
  double contact_radius_ratio = 0.0;  // largest contact radius / primary radius
};

struct SmallStrainCheck {
  StrainMeasure pair;   // particle-particle contacts
  StrainMeasure wall;   // contacts with the wall
  StrainMeasure worst;  // the larger of the two, each ratio
  StrainLimits limits;
  bool within = true;  // worst inside the limits
  bool bound = false;  // primaries of several radii: the measures are upper bounds
};

// The deepest overlaps a run reached, over R* (ContactEvents::deepest_overlap_ratio); nullopt for
// a kind of contact the run never had.
struct DeepestOverlaps {
  std::optional<double> pair;
  std::optional<double> wall;
};

// The small-strain check of a run. The contact radius follows from the overlap through the normal
// law; with primaries of several radii the extreme pairs bound both ratios (the primaries are of
// one material).
SmallStrainCheck check_small_strain(const DeepestOverlaps& deepest, const Particles& particles,
                                    const MaterialTable& materials, const Wall& wall, const ContactModelSpec& spec,
                                    const StrainLimits& limits = {});

}  // namespace aerobreak
