#pragma once
#include <string_view>

namespace aerobreak {

// schemas/openapi.json, compiled in by CMake, served at /api/openapi.json.
std::string_view openapi_text();

}  // namespace aerobreak
