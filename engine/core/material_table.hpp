#pragma once
#include <cstdint>
#include <vector>

#include "engine/core/material.hpp"

namespace aerobreak {

// The materials of a run and their pairwise effective constants, computed once.
class MaterialTable {
 public:
  explicit MaterialTable(std::vector<Material> materials) : materials_(std::move(materials)) {
    for (std::size_t m = 0; m < materials_.size(); ++m) materials_[m].validate("materials[" + std::to_string(m) + "]");
    const std::size_t n = materials_.size();
    pairs_.resize(n * n);
    for (std::size_t a = 0; a < n; ++a)
      for (std::size_t b = 0; b < n; ++b) pairs_[a * n + b] = combine(materials_[a], materials_[b]);
  }

  const Material& operator[](std::uint16_t m) const { return materials_[m]; }
  const PairMaterial& pair(std::uint16_t a, std::uint16_t b) const { return pairs_[a * materials_.size() + b]; }
  std::size_t size() const { return materials_.size(); }

 private:
  std::vector<Material> materials_;
  std::vector<PairMaterial> pairs_;
};

}  // namespace aerobreak
