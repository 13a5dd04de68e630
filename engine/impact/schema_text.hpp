#pragma once
#include <string_view>

namespace aerobreak {

// The text of schemas/case.schema.json and schemas/result.schema.json, compiled in by CMake
// (engine/impact/CMakeLists.txt), so that the schema files are the contract the code enforces.
std::string_view case_schema_text();
std::string_view result_schema_text();

}  // namespace aerobreak
