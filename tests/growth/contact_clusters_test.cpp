// Components of the contact graph, reassembled across the faces of a periodic box.
#include <catch2/catch.hpp>

#include "engine/growth/contact_clusters.hpp"
#include "tests/engine/support.hpp"

using namespace aerobreak;

namespace {

SimulationSettings bonded_in_box(double edge) {
  SimulationSettings settings = testing::bonded();
  settings.periodic = PeriodicBox{{edge, edge, edge}};
  return settings;
}

}  // namespace

TEST_CASE("a cluster across a corner of the box is reassembled in one piece") {
  const Particles cluster = testing::relaxed_cluster(25, 3);
  const double edge = 30.0;
  Particles shifted = cluster;
  // Primary 7 on the corner: the cluster is cut by all three pairs of faces.
  const Vec3 shift = Vec3{edge, edge, edge} - cluster.position[7];
  for (Vec3& x : shifted.position) x += shift;
  Simulation sim(shifted, {testing::unit_material(0.01)}, {}, ContactModelSpec{}, bonded_in_box(edge));
  const auto clusters = contact_clusters(sim);
  REQUIRE(clusters.size() == 1);
  const ContactCluster& c = clusters.front();
  CHECK(c.members.size() == 25);
  CHECK(c.contacts == sim.contacts().size());
  CHECK(c.image_contacts == 0);
  // Up to one translation (the root keeps its unwrapped position), the original geometry.
  for (std::size_t k = 0; k < c.members.size(); ++k) {
    const Vec3 expected = cluster.position[c.members[k]] - cluster.position[c.members[0]];
    CHECK(norm(c.position[k] - c.position[0] - expected) < 1e-12);
  }
}

TEST_CASE("components are listed largest first, monomers included") {
  Particles p = testing::relaxed_cluster(6, 1);
  for (std::size_t i = 0; i < 6; ++i) p.position[i] += Vec3{2.0, 2.0, 2.0};
  p.add({15.0, 15.0, 15.0}, 0.5, testing::unit_density());
  p.add({9.0, 15.0, 15.0}, 0.5, testing::unit_density());
  p.add({10.0, 15.0, 15.0}, 0.5, testing::unit_density());
  Simulation sim(std::move(p), {testing::unit_material(0.01)}, {}, ContactModelSpec{}, bonded_in_box(20.0));
  const auto clusters = contact_clusters(sim);
  REQUIRE(clusters.size() == 3);
  CHECK(clusters[0].members.size() == 6);
  CHECK(clusters[1].members.size() == 2);
  CHECK(clusters[1].contacts == 1);
  CHECK(clusters[2].members == std::vector<std::size_t>{6});
  CHECK(clusters[2].contacts == 0);
}

TEST_CASE("a chain that closes on its own image keeps one copy and counts the image contact") {
  // Eight touching spheres along x in a box eight diameters long: the last touches the first
  // through the face, a loop around the box that no finite copy can have.
  const double edge = 8.0;
  Particles chain;
  for (int k = 0; k < 8; ++k) chain.add({0.5 + k, 4.0, 4.0}, 0.5, testing::unit_density());
  Simulation sim(std::move(chain), {testing::unit_material(0.01)}, {}, ContactModelSpec{}, bonded_in_box(edge));
  const auto clusters = contact_clusters(sim);
  REQUIRE(clusters.size() == 1);
  CHECK(clusters[0].contacts == 8);
  CHECK(clusters[0].image_contacts == 1);
  double low = 1e9, high = -1e9;
  for (const Vec3& x : clusters[0].position) {
    low = std::min(low, x.x);
    high = std::max(high, x.x);
  }
  // One straight copy of the chain: seven diameters from end to end.
  CHECK(high - low == Approx(7.0).epsilon(1e-9));
}
