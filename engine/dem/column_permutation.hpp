#pragma once
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

}  // namespace aerobreak
