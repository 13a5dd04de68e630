#pragma once
#include <string_view>

namespace aerobreak {

// The text of schemas/study.schema.json, compiled in by CMake (orchestrator/study/CMakeLists.txt),
// so that the schema file is the contract the code enforces.
std::string_view study_schema_text();

}  // namespace aerobreak
