// A case's cluster read from a file is listed along its neighbours, as generated clusters are
// (docs/PERFORMANCE.md): whatever order the file had, its bonds join primaries close in index,
// and it holds the same primaries.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <tuple>
#include <unistd.h>

#include "engine/cluster/ballistic_aggregation.hpp"
#include "engine/cluster/cluster_contacts.hpp"
#include "engine/impact/impact_case.hpp"
#include "engine/impact/impact_run.hpp"
#include "engine/io/xyz.hpp"
#include "impact_support.hpp"

using namespace aerobreak;

namespace {

// The largest index distance between the two primaries of a bond.
std::size_t widest_bond(const Cluster& cluster) {
  std::size_t widest = 0;
  for (const auto& [i, j] : find_contacts(cluster, 1e-3).contacts) widest = std::max(widest, j - i);
  return widest;
}

Cluster cluster_of(const Particles& p) {
  Cluster c;
  c.position = p.position;
  c.radius = p.radius;
  return c;
}

}  // namespace

TEST_CASE("a cluster read from a file in any order is listed along its neighbours") {
  const Cluster generated = ballistic_cluster_cluster_aggregation({512, 1.0, 1.0}, 4);
  Cluster shuffled = generated;
  std::vector<std::size_t> order(generated.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::shuffle(order.begin(), order.end(), std::mt19937(7));
  for (std::size_t k = 0; k < order.size(); ++k) {
    shuffled.position[k] = generated.position[order[k]];
    shuffled.radius[k] = generated.radius[order[k]];
  }
  REQUIRE(widest_bond(shuffled) > 200);  // the control: a shuffled file has bonds far apart in index

  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("aerobreak_order_" + std::to_string(::getpid()) + ".xyz");
  write_xyz_cluster(file, shuffled);
  auto document = testing::minimal_case();
  document["cluster"] = {{"file", {{"path", file.string()}}}, {"relax", false}};
  RelaxationSummary relaxation;
  const Particles read = prepare_cluster(parse_impact_case(document), relaxation);
  std::filesystem::remove(file);

  const Cluster listed = cluster_of(read);
  CHECK(widest_bond(listed) <= widest_bond(generated) + 64);
  REQUIRE(listed.size() == generated.size());
  auto sorted = [](std::vector<Vec3> x) {
    std::sort(x.begin(), x.end(),
              [](const Vec3& a, const Vec3& b) { return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z); });
    return x;
  };
  const auto a = sorted(listed.position), b = sorted(generated.position);
  for (std::size_t i = 0; i < a.size(); ++i) CHECK(norm(a[i] - b[i]) < 1e-9);
}
