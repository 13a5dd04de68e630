#pragma once
#include <stdexcept>
#include <string>

namespace aerobreak {

// Bulk properties of one material, in any consistent unit system.
struct Material {
  double youngs_modulus = 0.0;  // E
  double poisson_ratio = 0.0;   // nu
  double density = 0.0;         // rho
  double surface_energy = 0.0;  // gamma, energy per area of ONE surface (report's convention)

  double shear_modulus() const { return youngs_modulus / (2.0 * (1.0 + poisson_ratio)); }
  void validate(const std::string& what) const;
};

// Effective elastic and adhesive constants of a pair of materials (docs/MODEL.md section 2).
// For identical materials these reduce exactly to the report's eqs 1-5, 7 and 11.
struct PairMaterial {
  double modulus = 0.0;           // E* = [(1-nu_i^2)/E_i + (1-nu_j^2)/E_j]^-1
  double shear = 0.0;             // G* = [(2-nu_i)/G_i + (2-nu_j)/G_j]^-1 (Mindlin, eq 11)
  double work_of_adhesion = 0.0;  // w = gamma_i + gamma_j (= 2 gamma for like materials)
};

PairMaterial combine(const Material& a, const Material& b);

}  // namespace aerobreak
