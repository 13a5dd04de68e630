#include "orchestrator/cli/text_table.hpp"

#include <algorithm>

namespace aerobreak {
namespace {

constexpr std::size_t kGap = 2;

std::vector<std::string> lines_of(const std::string& cell) {
  std::vector<std::string> lines;
  std::size_t begin = 0;
  for (std::size_t end; (end = cell.find('\n', begin)) != std::string::npos; begin = end + 1)
    lines.push_back(cell.substr(begin, end - begin));
  lines.push_back(cell.substr(begin));
  return lines;
}

std::vector<std::size_t> column_widths(const TextTable& table) {
  std::vector<std::size_t> widths(table.header.size(), 0);
  for (std::size_t c = 0; c < table.header.size(); ++c)
    for (const auto& line : lines_of(table.header[c])) widths[c] = std::max(widths[c], line.size());
  for (const auto& section : table.sections)
    for (const auto& row : section.rows)
      for (std::size_t c = 0; c < row.size() && c < widths.size(); ++c) widths[c] = std::max(widths[c], row[c].size());
  return widths;
}

// The columns of each block: the key columns, then as many of the others as fit in `width` (at
// least one, however wide).
std::vector<std::vector<std::size_t>> blocks_of(const std::vector<std::size_t>& widths, std::size_t keys,
                                                std::size_t width) {
  keys = std::min(keys, widths.size());
  std::size_t key_width = 0;
  for (std::size_t c = 0; c < keys; ++c) key_width += widths[c] + (c ? kGap : 0);
  std::vector<std::vector<std::size_t>> blocks;
  std::size_t used = 0;
  for (std::size_t c = keys; c < widths.size(); ++c) {
    const std::size_t added = (used ? kGap : 0) + widths[c];
    if (blocks.empty() || (blocks.back().size() > keys && used + added > width)) {
      blocks.emplace_back();
      for (std::size_t k = 0; k < keys; ++k) blocks.back().push_back(k);
      used = key_width;
    }
    used += (used ? kGap : 0) + widths[c];
    blocks.back().push_back(c);
  }
  if (blocks.empty()) {
    blocks.emplace_back();
    for (std::size_t k = 0; k < keys; ++k) blocks.back().push_back(k);
  }
  return blocks;
}

std::string line_of(const std::vector<std::string>& cells, const std::vector<std::size_t>& columns,
                    const std::vector<std::size_t>& widths) {
  std::string text;
  for (std::size_t k = 0; k < columns.size(); ++k) {
    const std::size_t c = columns[k];
    const std::string& cell = c < cells.size() ? cells[c] : std::string();
    text += cell;
    if (k + 1 < columns.size()) text += std::string(widths[c] - cell.size() + kGap, ' ');
  }
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text + "\n";
}

std::string header_lines(const TextTable& table, const std::vector<std::size_t>& columns,
                         const std::vector<std::size_t>& widths) {
  std::vector<std::vector<std::string>> split;
  std::size_t height = 0;
  for (const auto& cell : table.header) {
    split.push_back(lines_of(cell));
    height = std::max(height, split.back().size());
  }
  std::string text;
  for (std::size_t line = 0; line < height; ++line) {
    std::vector<std::string> cells;
    for (const auto& header : split) cells.push_back(line < header.size() ? header[line] : "");
    text += line_of(cells, columns, widths);
  }
  return text;
}

}  // namespace

std::string aligned_columns(const std::vector<std::vector<std::string>>& rows) {
  std::vector<std::size_t> widths;
  for (const auto& row : rows) {
    widths.resize(std::max(widths.size(), row.size()), 0);
    for (std::size_t c = 0; c < row.size(); ++c) widths[c] = std::max(widths[c], row[c].size());
  }
  std::string text;
  for (const auto& row : rows) {
    for (std::size_t c = 0; c < row.size(); ++c) {
      text += row[c];
      if (c + 1 < row.size()) text += std::string(widths[c] - row[c].size() + 2, ' ');
    }
    text += '\n';
  }
  return text;
}

std::vector<std::vector<std::string>>& TextTable::rows_of(const std::string& title) {
  const auto found = std::find_if(sections.begin(), sections.end(), [&](const Section& s) { return s.title == title; });
  return (found != sections.end() ? *found : sections.emplace_back(Section{title, {}})).rows;
}

std::string format_text_table(const TextTable& table, std::size_t width) {
  const auto widths = column_widths(table);
  std::string text;
  for (const auto& columns : blocks_of(widths, table.key_columns, width)) {
    if (!text.empty()) text += "\n";
    text += header_lines(table, columns, widths);
    for (std::size_t s = 0; s < table.sections.size(); ++s) {
      const auto& section = table.sections[s];
      if (!section.title.empty()) text += (s ? "\n" : "") + section.title + "\n";
      for (const auto& row : section.rows) text += line_of(row, columns, widths);
    }
  }
  return text;
}

}  // namespace aerobreak
