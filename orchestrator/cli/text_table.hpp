#pragma once
#include <string>
#include <vector>

namespace aerobreak {

// Rows of cells as text in aligned columns (two spaces between columns, one row a line): the
// outcome table and the critical-speed table of the command line.
std::string aligned_columns(const std::vector<std::vector<std::string>>& rows);

}  // namespace aerobreak
