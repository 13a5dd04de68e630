// The periodic box: nearest-image neighbour search against an explicit image sum, contacts across
// a face, momentum conservation through the images, unwrapped positions, and equality with the same
// run in open space.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <set>

#include "engine/dem/simulation.hpp"
#include "engine/neighbor/neighbor_search.hpp"
#include "support.hpp"

using namespace aerobreak;

namespace {

using PairSet = std::set<std::pair<std::uint32_t, std::uint32_t>>;

PairSet pair_set(const PairList& list) {
  PairSet pairs;
  for (std::uint32_t i = 0; i < list.particles(); ++i)
    for (std::uint32_t k = list.row_start[i]; k < list.row_start[i + 1]; ++k) pairs.insert({i, list.neighbor[k]});
  return pairs;
}

double into_box(double x, double edge) {
  const double r = std::fmod(x, edge);
  return r < 0.0 ? r + edge : r;
}

// Independent of PeriodicBox: with every centre put into the box by fmod, the pair is listed if
// any of the 27 copies of j shifted by -L, 0, +L per axis is in reach.
PairSet image_sum_pairs(std::vector<Vec3> x, const std::vector<double>& r, const PeriodicBox& box, double margin) {
  for (Vec3& p : x) p = {into_box(p.x, box.length.x), into_box(p.y, box.length.y), into_box(p.z, box.length.z)};
  PairSet pairs;
  for (std::uint32_t i = 0; i < x.size(); ++i)
    for (std::uint32_t j = i + 1; j < x.size(); ++j)
      for (int a = -1; a <= 1; ++a)
        for (int b = -1; b <= 1; ++b)
          for (int c = -1; c <= 1; ++c) {
            const Vec3 shift{a * box.length.x, b * box.length.y, c * box.length.z};
            const double reach = r[i] + r[j] + margin;
            if (norm2(x[j] + shift - x[i]) < reach * reach) pairs.insert({i, j});
          }
  return pairs;
}

Particles sphere_pair(const Vec3& a, const Vec3& b) {
  Particles p;
  p.add(a, 0.5, testing::unit_density());
  p.add(b, 0.5, testing::unit_density());
  return p;
}

SimulationSettings periodic(const Vec3& lengths) {
  SimulationSettings settings;
  settings.periodic = PeriodicBox{lengths};
  return settings;
}

}  // namespace

TEST_CASE("periodic cell-list and brute-force pairs equal the explicit image sum") {
  std::mt19937_64 rng(7);
  // Cubic and elongated boxes; the short edges of the last two hold only two or three cells.
  for (const Vec3 lengths : {Vec3{10.0, 10.0, 10.0}, Vec3{23.0, 7.0, 13.0}, Vec3{5.0, 6.5, 40.0}}) {
    const PeriodicBox box{lengths};
    for (bool polydisperse : {false, true}) {
      std::uniform_real_distribution<double> size(0.3, 0.8);
      std::uniform_real_distribution<double> unit(0.0, 1.0);
      std::vector<Vec3> position;
      std::vector<double> radius;
      for (int i = 0; i < 500; ++i) {
        // Most inside the box, some up to one edge outside it (as between two rebuilds), and a
        // cluster of them hugging the faces, where the images matter.
        const double spread = i % 5 == 0 ? 3.0 : 1.0;
        const double offset = i % 5 == 0 ? -1.0 : 0.0;
        Vec3 x{(offset + spread * unit(rng)) * lengths.x, (offset + spread * unit(rng)) * lengths.y,
               (offset + spread * unit(rng)) * lengths.z};
        if (i % 7 == 0) x.x = 0.3 * unit(rng);
        if (i % 11 == 0) x.y = lengths.y - 0.3 * unit(rng);
        position.push_back(x);
        radius.push_back(polydisperse ? size(rng) : 0.5);
      }
      for (double margin : {0.0, 0.3}) {
        PairList cells, brute;
        CellListSearch(box).find_pairs(position, radius, margin, cells);
        BruteForceSearch(box).find_pairs(position, radius, margin, brute);
        const PairSet reference = image_sum_pairs(position, radius, box, margin);
        INFO("box " << lengths.x << " x " << lengths.y << " x " << lengths.z << ", polydisperse " << polydisperse
                    << ", margin " << margin);
        REQUIRE(reference.size() > 100);
        CHECK(pair_set(brute) == reference);
        CHECK(pair_set(cells) == reference);
      }
    }
  }
}

TEST_CASE("a pair on opposite faces is listed through the boundary, and the box must fit the reach") {
  const PeriodicBox box{{6.0, 6.0, 6.0}};
  PairList list;
  CellListSearch(box).find_pairs({{0.1, 3.0, 3.0}, {5.2, 3.0, 3.0}}, {0.5, 0.5}, 0.0, list);
  CHECK(pair_set(list) == PairSet{{0, 1}});
  CellListSearch().find_pairs({{0.1, 3.0, 3.0}, {5.2, 3.0, 3.0}}, {0.5, 0.5}, 0.0, list);
  CHECK(list.pairs() == 0);
  // Reach 2 R + margin = 3.5 > 6 / 2: a pair could meet through two images.
  CHECK_THROWS_AS(CellListSearch(box).find_pairs({{0, 0, 0}, {1, 1, 1}}, {0.5, 0.5}, 2.5, list), std::invalid_argument);
  CHECK_THROWS_AS(BruteForceSearch(box).find_pairs({{0, 0, 0}, {1, 1, 1}}, {0.5, 0.5}, 2.5, list),
                  std::invalid_argument);
}

TEST_CASE("the simulation rejects walls or gravity with a periodic box and boxes too small for the reach") {
  const ContactModelSpec spec;
  CHECK_THROWS_AS(
      Simulation(sphere_pair({1, 1, 1}, {3, 3, 3}), {testing::unit_material()}, {Wall{}}, spec, periodic({8, 8, 8})),
      std::invalid_argument);
  SimulationSettings falling = periodic({8, 8, 8});
  falling.body.gravity = {0.0, 0.0, -1e-3};
  CHECK_THROWS_AS(Simulation(sphere_pair({1, 1, 1}, {3, 3, 3}), {testing::unit_material()}, {}, spec, falling),
                  std::invalid_argument);
  CHECK_THROWS_AS(
      Simulation(sphere_pair({1, 1, 1}, {3, 3, 3}), {testing::unit_material()}, {}, spec, periodic({2, 8, 8})),
      std::invalid_argument);
  CHECK_THROWS_AS(
      Simulation(sphere_pair({1, 1, 1}, {3, 3, 3}), {testing::unit_material()}, {}, spec, periodic({-8, 8, 8})),
      std::invalid_argument);
}

TEST_CASE("a pair straddling the boundary forms a JKR contact and settles at the equilibrium overlap") {
  // Centres 0.2 and L - 0.79 along x: 0.99 apart through the face x = 0, L - 0.99 apart inside.
  const double edge = 8.0;
  for (bool brute : {false, true}) {
    SimulationSettings settings = periodic({edge, edge, edge});
    settings.brute_force_neighbors = brute;
    // Drag without noise takes out the oscillation (as relax_cluster does).
    settings.body.langevin.drag_per_diameter = 0.05;
    ContactModelSpec spec;
    spec.tangential = false;
    Simulation sim(sphere_pair({0.2, 4.0, 4.0}, {edge - 0.79, 4.0, 4.0}), {testing::unit_material(0.01)}, {}, spec,
                   settings);
    REQUIRE(sim.contacts().size() == 1);
    sim.run(20000);
    REQUIRE(sim.contacts().size() == 1);
    // Zero-load JKR overlap a0^2 / (3 R*) (eqs 2, 4), R* = 1/4.
    double a0 = 0.0;
    sim.contacts().for_each([&](const ContactState& c) { a0 = c.constants.equilibrium_radius; });
    const double equilibrium = a0 * a0 / (3.0 * 0.25);
    const double overlap = 1.0 - norm(sim.separation(0, 1));
    INFO("brute-force neighbours " << brute);
    CHECK(overlap == Approx(equilibrium).epsilon(1e-6));
    // The contact pulled the spheres together through the face: the sum of their separations
    // inside the box is the box edge minus the centre distance.
    CHECK(std::fabs(sim.particles().position[1].x - sim.particles().position[0].x) ==
          Approx(edge - (1.0 - overlap)).epsilon(1e-9));
  }
}

TEST_CASE("linear momentum is conserved through the periodic images") {
  // A dense gas of sticky spheres in a small box: many contacts form, break and cross the faces.
  const double edge = 7.0;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> gauss(0.0, 0.2);
  Particles p;
  while (p.size() < 60) {
    const Vec3 x{edge * unit(rng), edge * unit(rng), edge * unit(rng)};
    bool clear = true;
    for (const Vec3& y : p.position) clear = clear && norm2(PeriodicBox{{edge, edge, edge}}.minimum_image(y - x)) > 1.0;
    if (!clear) continue;
    const std::size_t i = p.add(x, 0.5, testing::unit_density());
    p.velocity[i] = {gauss(rng), gauss(rng), gauss(rng)};
    p.angular_velocity[i] = {gauss(rng), gauss(rng), gauss(rng)};
  }
  Simulation sim(std::move(p), {testing::unit_material(0.01)}, {}, testing::full_model(), periodic({edge, edge, edge}));
  const Vec3 momentum0 = testing::linear_momentum(sim.particles());
  double scale = 0.0;
  for (std::size_t i = 0; i < sim.particles().size(); ++i)
    scale += sim.particles().mass[i] * norm(sim.particles().velocity[i]);
  std::size_t across = 0;
  for (int k = 0; k < 40; ++k) {
    sim.run(500);
    // Contacts whose partners sit more than half a box apart inside the box act through a face.
    sim.contacts().for_each([&](const ContactState& c) {
      if (norm(sim.particles().position[c.j] - sim.particles().position[c.i]) > 0.5 * edge) ++across;
    });
  }
  std::int64_t wraps = 0;
  for (const ImageCount& n : sim.images()) wraps += std::abs(n.x) + std::abs(n.y) + std::abs(n.z);
  REQUIRE(sim.pair_events().made > 20);
  REQUIRE(sim.pair_events().broken > 0);
  REQUIRE(across > 0);
  REQUIRE(wraps > 10);
  for (const Vec3& x : sim.particles().position) {
    // Wrapped at the last rebuild; since then nobody has moved more than half the skin.
    CHECK(x.x > -0.5);
    CHECK(x.x < edge + 0.5);
  }
  CHECK(norm(testing::linear_momentum(sim.particles()) - momentum0) < 1e-12 * scale);
}

TEST_CASE("unwrapped positions follow a free particle through many boxes") {
  const double edge = 5.0;
  Particles p;
  p.add({1.0, 1.0, 1.0}, 0.5, testing::unit_density());
  p.velocity[0] = {0.7, -0.3, 0.05};
  SimulationSettings settings = periodic({edge, edge, edge});
  settings.time_step = 0.05;
  Simulation sim(std::move(p), {testing::unit_material(0.01)}, {}, ContactModelSpec{}, settings);
  sim.run(2000);
  const Vec3 expected = Vec3{1.0, 1.0, 1.0} + sim.time() * Vec3{0.7, -0.3, 0.05};
  const Vec3 unwrapped = sim.unwrapped_positions()[0];
  CHECK(unwrapped.x == Approx(expected.x).epsilon(1e-12));
  CHECK(unwrapped.y == Approx(expected.y).epsilon(1e-12));
  CHECK(unwrapped.z == Approx(expected.z).epsilon(1e-12));
  // 70 d along x and -30 d along y: 14 and -6 boxes, less what the last rebuild has not wrapped yet.
  CHECK(sim.images()[0].x >= 13);
  CHECK(sim.images()[0].y <= -5);
}

TEST_CASE("a cluster across a corner of the box moves exactly as in open space") {
  // The same relaxed, spinning cluster, once in open space and once shifted so that it straddles
  // a corner of a periodic box: the nearest-image separations equal the open-space ones.
  Particles cluster = testing::relaxed_cluster(30, 5);
  std::mt19937_64 rng(1);
  std::normal_distribution<double> gauss(0.0, 0.05);
  for (std::size_t i = 0; i < cluster.size(); ++i) {
    cluster.velocity[i] = {gauss(rng), gauss(rng), gauss(rng)};
    cluster.angular_velocity[i] = {gauss(rng), gauss(rng), gauss(rng)};
  }
  const double edge = 40.0;
  Particles shifted = cluster;
  const Vec3 shift = Vec3{edge, edge, edge} - cluster.position[0];  // primary 0 sits on the corner
  for (Vec3& x : shifted.position) x += shift;
  SimulationSettings open = testing::bonded();
  open.adaptive_time_step = false;  // a periodic box keeps one step per run (docs/MODEL.md 9.2)
  SimulationSettings box = testing::bonded();
  box.periodic = PeriodicBox{{edge, edge, edge}};
  Simulation a(std::move(cluster), {testing::unit_material(0.01)}, {}, testing::full_model(), open);
  Simulation b(std::move(shifted), {testing::unit_material(0.01)}, {}, testing::full_model(), box);
  REQUIRE(a.contacts().size() == b.contacts().size());
  a.run(3000);
  b.run(3000);
  REQUIRE(a.pair_events().made == b.pair_events().made);
  REQUIRE(a.pair_events().broken == b.pair_events().broken);
  double worst = 0.0;
  for (std::size_t i = 1; i < a.particles().size(); ++i)
    worst = std::max(worst, norm(a.separation(0, i) - b.separation(0, i)));
  std::int64_t wrapped = 0;
  for (const ImageCount& n : b.images()) wrapped += std::abs(n.x) + std::abs(n.y) + std::abs(n.z);
  REQUIRE(wrapped > 0);
  // Only round-off: the shift by 40 d costs a few ulps of 40 in every coordinate.
  CHECK(worst < 1e-9);
  const std::vector<Vec3> unwrapped = b.unwrapped_positions();
  for (std::size_t i = 0; i < a.particles().size(); ++i)
    CHECK(norm(unwrapped[i] - shift - a.particles().position[i]) < 1e-9);
}
