#pragma once
#include <vector>

#include "engine/impact/json_schema.hpp"
#include "orchestrator/study/study.hpp"

namespace aerobreak {

// The cases of a study, and why those that are not valid cases are not (each distinct violation
// once, naming the first grid point and replicate that shows it and how many others do).
struct StudyExpansion {
  std::vector<StudyCase> cases;
  std::vector<SchemaViolation> violations;
};

StudyExpansion expand_with_violations(const Study& study);

// "impact_speed=0.01 gamma_over_kn=0.001 primaries=16": a grid point as people read it.
std::string grid_label(const nlohmann::ordered_json& grid_point);

}  // namespace aerobreak
