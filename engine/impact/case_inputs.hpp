#pragma once
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>

#include "engine/core/material.hpp"
#include "engine/core/units.hpp"

namespace aerobreak {

// What a case document says of the physics of its impact, in reduced units (d, m, tau =
// sqrt(m/k_n), docs/MODEL.md 1.2). Read by one function for every reader: the engine's case
// (parse_impact_case), the store (each case's N, kept beside its document) and the lookup tables
// (a grid point's inputs, from its stored case).
struct CaseInputs {
  std::optional<PhysicalScaling> physical;  // set for "units": "physical": its material, d and softening
  Material material;                        // the primaries', reduced (E in k_n/d, gamma in k_n)
  double speed = 0.0;                       // d/tau
  double angle_degrees = 0.0;               // from head-on
  std::optional<std::int64_t> primaries;    // N of a generated cluster; none for a cluster file
  std::optional<double> fractal_dimension;  // the generator's target D_f; none for ballistic clusters and files
};

// Reads a case document completed with the schema's defaults (schemas/case.schema.json). It
// checks nothing: a number the document lacks (a store's damaged or foreign document) reads as
// NaN, N and D_f as none.
CaseInputs read_case_inputs(const nlohmann::ordered_json& document);

}  // namespace aerobreak
