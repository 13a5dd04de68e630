// Gaps between groups of particles in a periodic box (growth/cluster_proximity.hpp) against a
// brute-force pass over every pair of particles through their nearest images.
#include <catch2/catch.hpp>

#include <algorithm>
#include <limits>
#include <vector>

#include "engine/cluster/random_stream.hpp"
#include "engine/growth/cluster_proximity.hpp"

using namespace aerobreak;

TEST_CASE("group gaps are exact within the search gap and lower bounds beyond, close pairs complete") {
  const PeriodicBox box{{20.0, 20.0, 20.0}};
  RandomStream random(3);
  // 30 groups of 1-6 particles: a random walk of touching unit spheres from a random start.
  std::vector<Vec3> position;
  std::vector<double> radius;
  std::vector<std::uint32_t> group;
  std::vector<BoundingSphere> spheres;
  const std::size_t groups = 30;
  for (std::uint32_t g = 0; g < groups; ++g) {
    Vec3 x{20.0 * random.uniform(), 20.0 * random.uniform(), 20.0 * random.uniform()};
    const std::size_t size = 1 + static_cast<std::size_t>(6.0 * random.uniform());
    std::vector<Vec3> members;
    for (std::size_t k = 0; k < size; ++k) {
      members.push_back(x);
      x += random.unit_vector();
    }
    Vec3 centre;
    for (const Vec3& m : members) centre += m / static_cast<double>(size);
    double reach = 0.0;
    for (const Vec3& m : members) {
      reach = std::max(reach, norm(m - centre) + 0.5);
      position.push_back(m);
      radius.push_back(0.5);
      group.push_back(g);
    }
    spheres.push_back({centre, reach});
  }
  std::vector<double> exact(groups, std::numeric_limits<double>::infinity());
  std::vector<std::pair<std::uint32_t, std::uint32_t>> close;
  std::vector<std::vector<double>> pair_gap(groups,
                                            std::vector<double>(groups, std::numeric_limits<double>::infinity()));
  for (std::size_t i = 0; i < position.size(); ++i)
    for (std::size_t j = i + 1; j < position.size(); ++j) {
      if (group[i] == group[j]) continue;
      const double gap = norm(box.minimum_image(position[j] - position[i])) - 1.0;
      const auto a = std::min(group[i], group[j]), b = std::max(group[i], group[j]);
      pair_gap[a][b] = std::min(pair_gap[a][b], gap);
      exact[a] = std::min(exact[a], gap);
      exact[b] = std::min(exact[b], gap);
    }
  for (std::uint32_t a = 0; a < groups; ++a)
    for (std::uint32_t b = a + 1; b < groups; ++b)
      if (pair_gap[a][b] < 1.0) close.emplace_back(a, b);

  for (bool with_spheres : {false, true}) {
    GroupProximitySearch search(box, 2.0);
    const GroupProximity found =
        search.find(position, radius, group, groups, with_spheres ? spheres : std::vector<BoundingSphere>{}, 1.0);
    INFO((with_spheres ? "with" : "without") << " bounding spheres");
    REQUIRE(found.gap.size() == groups);
    for (std::size_t g = 0; g < groups; ++g) {
      if (exact[g] < 2.0) CHECK(found.gap[g] == Approx(exact[g]).margin(1e-12));
      CHECK(found.gap[g] <= exact[g] + 1e-12);
      if (!with_spheres && exact[g] >= 2.0) CHECK(found.gap[g] == 2.0);
    }
    std::vector<std::pair<std::uint32_t, std::uint32_t>> listed = found.close;
    std::sort(listed.begin(), listed.end());
    CHECK(listed == close);
  }
}
