// The cell-list search lists exactly the pairs the O(N^2) reference lists.
#include <catch2/catch.hpp>

#include <random>
#include <set>

#include "engine/neighbor/neighbor_search.hpp"

using namespace aerobreak;

namespace {

std::set<std::pair<std::uint32_t, std::uint32_t>> pair_set(const PairList& list) {
  std::set<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (std::uint32_t i = 0; i < list.particles(); ++i)
    for (std::uint32_t k = list.row_start[i]; k < list.row_start[i + 1]; ++k) pairs.insert({i, list.neighbor[k]});
  return pairs;
}

bool rows_sorted(const PairList& list) {
  for (std::uint32_t i = 0; i < list.particles(); ++i)
    for (std::uint32_t k = list.row_start[i] + 1; k < list.row_start[i + 1]; ++k)
      if (list.neighbor[k - 1] >= list.neighbor[k]) return false;
  return true;
}

}  // namespace

TEST_CASE("cell-list pairs equal brute-force pairs for dense, spread and polydisperse sets") {
  std::mt19937_64 rng(42);
  for (double spread : {3.0, 30.0, 1e6}) {
    for (bool polydisperse : {false, true}) {
      std::uniform_real_distribution<double> place(-spread, spread);
      std::uniform_real_distribution<double> size(0.2, 1.5);
      std::vector<Vec3> position;
      std::vector<double> radius;
      // A dense blob near the origin plus particles scattered far out.
      for (int i = 0; i < 600; ++i) {
        const double s = i < 400 ? 3.0 : spread;
        std::uniform_real_distribution<double> near(-s, s);
        position.push_back({near(rng), near(rng), near(rng)});
        radius.push_back(polydisperse ? size(rng) : 0.5);
      }
      for (double margin : {0.0, 0.1, 0.7}) {
        PairList cells, brute;
        CellListSearch{}.find_pairs(position, radius, margin, cells);
        BruteForceSearch{}.find_pairs(position, radius, margin, brute);
        INFO("spread " << spread << ", polydisperse " << polydisperse << ", margin " << margin);
        REQUIRE(brute.pairs() > 0);
        CHECK(pair_set(cells) == pair_set(brute));
        CHECK(rows_sorted(cells));
        CHECK(cells.contact == std::vector<std::int32_t>(cells.pairs(), -1));
      }
    }
  }
}

TEST_CASE("empty and single-particle sets give no pairs") {
  PairList list;
  CellListSearch search;
  search.find_pairs({}, {}, 0.1, list);
  CHECK(list.pairs() == 0);
  search.find_pairs({{0, 0, 0}}, {0.5}, 0.1, list);
  CHECK(list.pairs() == 0);
  CHECK(list.row_start == std::vector<std::uint32_t>{0, 0});
}
