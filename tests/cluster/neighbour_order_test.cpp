// ordered_along_neighbours lists a cluster's primaries breadth-first over the graph of neighbours.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <random>
#include <tuple>
#include <vector>

#include "engine/cluster/ballistic_aggregation.hpp"
#include "engine/cluster/cluster_contacts.hpp"
#include "engine/cluster/neighbour_order.hpp"

using namespace aerobreak;

namespace {

Cluster shuffled(const Cluster& c, std::uint64_t seed) {
  std::vector<std::size_t> order(c.size());
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937_64(seed));
  Cluster s;
  for (std::size_t i : order) {
    s.position.push_back(c.position[i]);
    s.radius.push_back(c.radius[i]);
  }
  return s;
}

std::vector<std::tuple<double, double, double, double>> sorted_primaries(const Cluster& c) {
  std::vector<std::tuple<double, double, double, double>> p;
  for (std::size_t i = 0; i < c.size(); ++i)
    p.emplace_back(c.position[i].x, c.position[i].y, c.position[i].z, c.radius[i]);
  std::sort(p.begin(), p.end());
  return p;
}

std::size_t widest_contact(const ContactGraph& graph) {
  std::size_t widest = 0;
  for (const auto& [i, j] : graph.contacts) widest = std::max(widest, j - i);
  return widest;
}

// Neighbours as ordered_along_neighbours takes them by default: surfaces within 0.5 (r_i + r_j).
ContactGraph neighbours(const Cluster& c) { return find_contacts(c, 0.5); }

// Breadth-first: every primary after the first of its component neighbours an earlier one, and
// the earliest neighbour of each (its parent in the walk) never comes before the previous
// primary's parent.
void require_breadth_first(const Cluster& c) {
  const ContactGraph graph = neighbours(c);
  std::vector<std::size_t> parent(c.size(), c.size());
  for (const auto& [i, j] : graph.contacts) parent[j] = std::min(parent[j], i);
  std::size_t previous = 0;
  for (std::size_t k = 1; k < c.size(); ++k) {
    if (parent[k] == c.size()) continue;  // the first primary of a further component
    CHECK(parent[k] >= previous);
    previous = parent[k];
  }
}

}  // namespace

TEST_CASE("ordering along neighbours keeps the primaries and puts neighbours close in index") {
  const std::size_t n = 4096;
  const Cluster scattered = shuffled(ballistic_cluster_cluster_aggregation({n, 1.0, 1.0}, 21), 5);
  const Cluster ordered = ordered_along_neighbours(scattered);
  REQUIRE(ordered.size() == n);
  CHECK(sorted_primaries(ordered) == sorted_primaries(scattered));
  const ContactGraph before = neighbours(scattered), after = neighbours(ordered);
  CHECK(after.contacts.size() == before.contacts.size());
  CHECK(find_contacts(ordered).contacts.size() == find_contacts(scattered).contacts.size());
  require_breadth_first(ordered);
  // Shuffled, neighbours lie anywhere (about n/3 apart on average, up to n); a fractal aggregate
  // is thin, so ordered they lie within a few breadth-first levels.
  CHECK(widest_contact(before) > n / 2);
  CHECK(widest_contact(after) < n / 32);
}

TEST_CASE("ordering along neighbours lists each component after the one before, whole") {
  // Two chains of touching unit spheres, far apart, their primaries interleaved.
  Cluster c;
  for (int k = 0; k < 10; ++k) {
    c.position.push_back({static_cast<double>(k), 0.0, 0.0});
    c.radius.push_back(0.5);
    c.position.push_back({static_cast<double>(k), 50.0, 0.0});
    c.radius.push_back(0.5);
  }
  const Cluster ordered = ordered_along_neighbours(c);
  REQUIRE(ordered.size() == 20);
  for (std::size_t k = 0; k < 20; ++k) CHECK(ordered.position[k].y == (k < 10 ? 0.0 : 50.0));
  // Each chain from one end to the other: a breadth-first walk starts at an end of the graph.
  for (std::size_t k = 1; k < 10; ++k) CHECK(std::abs(ordered.position[k].x - ordered.position[k - 1].x) == 1.0);
  CHECK((ordered.position[0].x == 0.0 || ordered.position[0].x == 9.0));
  require_breadth_first(ordered);
}
