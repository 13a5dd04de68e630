// MELCOR 2 tabular functions (docs/EXPORT.md, "MELCOR"). Input syntax after the MELCOR Computer
// Code Manuals, Vol. 1: Primer and Users' Guide (SAND2017-0455 O), TF package: a TF_INPUT block,
// per function TF_ID 'name' scale and TF_TAB n followed by n records "i x y"; '!' starts a comment.
#include <cstdio>

#include "orchestrator/export/adapter_groups.hpp"
#include "orchestrator/export/table_formats.hpp"

namespace aerobreak {
namespace {

struct TabulatedQuantity {
  const char* column;
  const char* tag;  // in the function's name: at most 16 characters in all
};
constexpr TabulatedQuantity kQuantities[] = {
    {"p_stick", "PSTK"}, {"p_break_up", "PBRK"}, {"retained_mass_fraction", "RETN"}, {"to_wall", "WALL"}};

std::string condition_comment(const ConditionRows& condition) {
  std::string text = "!";
  for (const auto& [name, value] : condition.key) text += " " + name + " = " + number_text(value);
  return text + "\n";
}

std::string tabular_function(const LookupTable& table, const TableColumn& quantity, const char* tag, std::size_t number,
                             const ConditionRows& condition) {
  const auto& speed = adapter_speed(table);
  char name[40];
  std::snprintf(name, sizeof name, "AB_%s_%03zu", tag, number);
  std::string text = "!\n! " + quantity.name + " (" + quantity.description + ") against impact speed [" + speed.unit + "]\n" +
                     condition_comment(condition) + "TF_ID '" + name + "' 1.0\nTF_TAB " +
                     std::to_string(condition.rows.size()) + " ! n x y\n";
  std::size_t i = 0;
  for (const std::size_t row : condition.rows)
    text += "  " + std::to_string(++i) + "  " + number_text(speed.values[row]) + "  " + number_text(quantity.values[row]) + "\n";
  return text;
}

}  // namespace

std::string melcor_text(const LookupTable& table) {
  std::string text = "! aerobreak lookup table as MELCOR 2 tabular functions (docs/EXPORT.md)\n";
  for (const auto& [key, value] : metadata_lines(table.metadata)) text += "! " + key + ": " + value + "\n";
  text += "TF_INPUT\n";
  for (const auto& quantity : kQuantities) {
    const auto* column = table.find(quantity.column);
    if (!column) continue;
    std::size_t number = 0;
    for (const auto& condition : condition_rows(table, *column))
      text += tabular_function(table, *column, quantity.tag, ++number, condition);
  }
  return text;
}

}  // namespace aerobreak
