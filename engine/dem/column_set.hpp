#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace aerobreak {

// Moves element order[k] of a column to position k (a column of a structure of arrays).
template <class T>
void permute_column(std::vector<T>& column, const std::vector<std::int32_t>& order) {
  std::vector<T> packed;
  packed.reserve(order.size());
  for (std::int32_t from : order) packed.push_back(column[from]);
  column = std::move(packed);
}

// Resizing and permuting for a class that keeps its fields as columns of doubles (a structure of
// arrays) and lists them in `columns()`.
template <class Derived>
class ColumnSet {
 public:
  void resize(std::size_t rows) {
    for (std::vector<double>* column : static_cast<Derived*>(this)->columns()) column->resize(rows);
  }
  // Moves row order[k] to row k.
  void permute(const std::vector<std::int32_t>& order) {
    for (std::vector<double>* column : static_cast<Derived*>(this)->columns()) permute_column(*column, order);
  }
};

}  // namespace aerobreak
