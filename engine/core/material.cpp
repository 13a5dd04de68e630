#include "engine/core/material.hpp"

#include <cmath>

namespace aerobreak {

void Material::validate(const std::string& what) const {
  auto require = [&](bool ok, const char* field, const char* rule) {
    if (!ok) throw std::invalid_argument(what + "." + field + " must be " + rule);
  };
  require(std::isfinite(youngs_modulus) && youngs_modulus > 0.0, "youngs_modulus", "positive");
  require(std::isfinite(poisson_ratio) && poisson_ratio > -1.0 && poisson_ratio < 0.5, "poisson_ratio", "in (-1, 0.5)");
  require(std::isfinite(density) && density > 0.0, "density", "positive");
  require(std::isfinite(surface_energy) && surface_energy >= 0.0, "surface_energy", "non-negative");
}

PairMaterial combine(const Material& a, const Material& b) {
  PairMaterial pair;
  pair.modulus = 1.0 / ((1.0 - a.poisson_ratio * a.poisson_ratio) / a.youngs_modulus +
                        (1.0 - b.poisson_ratio * b.poisson_ratio) / b.youngs_modulus);
  pair.shear = 1.0 / ((2.0 - a.poisson_ratio) / a.shear_modulus() + (2.0 - b.poisson_ratio) / b.shear_modulus());
  pair.work_of_adhesion = a.surface_energy + b.surface_energy;
  return pair;
}

}  // namespace aerobreak
