#pragma once
#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include "engine/cluster/random_stream.hpp"

namespace aerobreak {

// An index uniform on {0, ..., count - 1} (count >= 1) from one uniform draw; written out rather
// than std::uniform_int_distribution so the sequence is fixed by the seed alone.
inline std::size_t uniform_index(RandomStream& random, std::size_t count) {
  const auto i = static_cast<std::size_t>(random.uniform() * static_cast<double>(count));
  return std::min(i, count - 1);
}

// Fisher-Yates shuffle (std::shuffle's draws are implementation-defined).
template <class T>
void shuffle(std::vector<T>& items, RandomStream& random) {
  for (std::size_t i = items.size(); i > 1; --i) {
    std::swap(items[i - 1], items[uniform_index(random, i)]);
  }
}

}  // namespace aerobreak
