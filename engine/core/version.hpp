#pragma once
#include <string_view>

namespace aerobreak {

// Release version (CMake project version) and the git commit the binary was built from.
std::string_view version();
std::string_view git_commit();

}  // namespace aerobreak
