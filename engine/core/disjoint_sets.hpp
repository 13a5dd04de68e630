#pragma once
#include <cstddef>
#include <numeric>
#include <vector>

namespace aerobreak {

// Union-find over the elements 0 .. n-1, with path halving. A set's representative is its lowest
// element, so representatives, and whatever is ordered by them, do not depend on the order in
// which sets were joined.
class DisjointSets {
 public:
  explicit DisjointSets(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), std::size_t{0}); }

  std::size_t find(std::size_t i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  void unite(std::size_t a, std::size_t b) {
    a = find(a);
    b = find(b);
    if (a < b)
      parent_[b] = a;
    else
      parent_[a] = b;
  }
  std::size_t size() const { return parent_.size(); }

 private:
  std::vector<std::size_t> parent_;
};

}  // namespace aerobreak
