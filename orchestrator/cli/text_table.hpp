#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace aerobreak {

// Rows of cells as text in aligned columns (two spaces between columns, one row a line): the list
// of fits of the command line.
std::string aligned_columns(const std::vector<std::vector<std::string>>& rows);

// A table of the command line: a header (a cell may hold several lines, split at '\n'), then rows,
// in sections that each open with a title line (a section without a title has none).
struct TextTable {
  struct Section {
    std::string title;
    std::vector<std::vector<std::string>> rows;
  };
  std::vector<std::string> header;
  std::vector<Section> sections;
  std::size_t key_columns = 1;  // the leading columns that name a row, repeated in every block

  // The rows of the section titled `title`: a new section at the end if there is none yet.
  std::vector<std::vector<std::string>>& rows_of(const std::string& title);
};

// The table as text in aligned columns, at most `width` characters a line where it can be: columns
// that do not fit go into a further block below, which repeats the key columns. Sections are set
// apart by an empty line; their columns line up across sections and blocks.
std::string format_text_table(const TextTable& table, std::size_t width = 100);

}  // namespace aerobreak
