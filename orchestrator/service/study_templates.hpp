#pragma once
#include <nlohmann/json.hpp>
#include <string_view>

namespace aerobreak {

// studies/default.study.json, compiled in by CMake: the study README's first command runs.
std::string_view default_study_text();

// GET /api/templates: the studies a user may start from (the dashboard's submit page offers
// them), each with its name, the repository file it comes from and its document (without the
// file's "$schema" reference). Today one: the default study.
const nlohmann::ordered_json& study_templates_json();

}  // namespace aerobreak
