// Union-find: the sets follow the unions, and a set's representative is its lowest element
// whatever the order of the unions.
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <utility>
#include <vector>

#include "engine/core/disjoint_sets.hpp"

using namespace aerobreak;

namespace {

// Reference: labels relaxed to the lowest label of any linked element until nothing changes.
std::vector<std::size_t> lowest_linked(std::size_t n, const std::vector<std::pair<std::size_t, std::size_t>>& links) {
  std::vector<std::size_t> label(n);
  for (std::size_t i = 0; i < n; ++i) label[i] = i;
  for (bool changed = true; changed;) {
    changed = false;
    for (const auto& [a, b] : links) {
      const std::size_t low = std::min(label[a], label[b]);
      changed = changed || label[a] != low || label[b] != low;
      label[a] = label[b] = low;
    }
  }
  return label;
}

}  // namespace

TEST_CASE("disjoint sets join as the links say and are represented by their lowest element") {
  std::mt19937_64 random(42);
  const std::size_t n = 300;
  std::uniform_int_distribution<std::size_t> element(0, n - 1);
  std::vector<std::pair<std::size_t, std::size_t>> links;
  for (int k = 0; k < 220; ++k) links.emplace_back(element(random), element(random));
  const std::vector<std::size_t> expected = lowest_linked(n, links);

  for (int order = 0; order < 3; ++order) {
    std::shuffle(links.begin(), links.end(), random);
    DisjointSets sets(n);
    for (const auto& [a, b] : links) sets.unite(a, b);
    for (std::size_t i = 0; i < n; ++i) CHECK(sets.find(i) == expected[i]);
  }
}

TEST_CASE("disjoint sets start as singletons and joining a set with itself changes nothing") {
  DisjointSets sets(4);
  sets.unite(2, 2);
  for (std::size_t i = 0; i < 4; ++i) CHECK(sets.find(i) == i);
  sets.unite(3, 1);
  sets.unite(1, 3);
  CHECK(sets.find(3) == 1);
  CHECK(sets.find(1) == 1);
  CHECK(sets.find(0) == 0);
  CHECK(sets.find(2) == 2);
}
