#pragma once
#include <cstdint>
#include <vector>

namespace aerobreak {

// Half neighbour list in compressed-row form: the partners j > i of particle i are
// neighbor[row_start[i] .. row_start[i+1]), sorted by j. contact[k] is the contact-pool slot of
// the pair neighbor[k], or -1 while the pair is not in contact.
struct PairList {
  std::vector<std::uint32_t> row_start;
  std::vector<std::uint32_t> neighbor;
  std::vector<std::int32_t> contact;

  std::size_t particles() const { return row_start.empty() ? 0 : row_start.size() - 1; }
  std::size_t pairs() const { return neighbor.size(); }
};

}  // namespace aerobreak
