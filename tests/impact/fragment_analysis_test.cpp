// Fragments (connected components of the contact graph), the outcome rule and the settle
// judgement on constructed states with known answers.
#include <catch2/catch.hpp>

#include <numbers>

#include "engine/impact/fragments.hpp"
#include "engine/impact/outcome.hpp"
#include "engine/impact/settle.hpp"

using namespace aerobreak;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

const double density = 6.0 / std::numbers::pi;  // unit mass per unit-diameter sphere

// Two separate chains (3 and 2 primaries) and a monomer; the 3-chain rests on the wall, the
// 2-chain flies away from it, the monomer moves along it.
struct Scene {
  Particles p;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> contacts{{0, 1}, {1, 2}, {3, 4}};
  std::vector<std::uint32_t> wall_contacts{1, 0, 0, 0, 0, 0};
};

Scene scene() {
  Scene s;
  for (double x : {0.0, 1.0, 2.0}) s.p.add({x, 0.0, 0.5}, 0.5, density);
  s.p.add({10.0, 0.0, 5.0}, 0.5, density);
  s.p.add({11.0, 0.0, 5.0}, 0.5, density);
  s.p.add({-10.0, 0.0, 0.6}, 0.5, density);
  s.p.velocity[3] = {0.0, 0.0, 0.2};
  s.p.velocity[4] = {0.0, 0.0, 0.4};
  s.p.velocity[5] = {-1.0, 0.0, 0.0};
  return s;
}

Fragment fragment(std::size_t size, bool on_wall, double normal_velocity) {
  Fragment f;
  f.size = size;
  f.mass = static_cast<double>(size);
  f.wall_contacts = on_wall ? 1 : 0;
  f.normal_velocity = normal_velocity;
  f.velocity = {0.0, 0.0, normal_velocity};
  return f;
}

}  // namespace

TEST_CASE("fragments are the connected components of the contact graph, monomers included") {
  const Scene s = scene();
  const FragmentAnalysis a = find_fragments(s.p, s.contacts, s.wall_contacts, Wall{});
  REQUIRE(a.fragments.size() == 3);
  const Fragment& chain = a.fragments[0];
  const Fragment& pair = a.fragments[1];
  const Fragment& monomer = a.fragments[2];
  CHECK(chain.size == 3);
  CHECK(pair.size == 2);
  CHECK(monomer.size == 1);
  CHECK(chain.first_primary == 0);
  CHECK(pair.first_primary == 3);
  CHECK(monomer.first_primary == 5);
  CHECK(a.fragment_of == std::vector<std::uint32_t>{0, 0, 0, 1, 1, 2});

  CHECK(chain.on_wall());
  CHECK(chain.wall_contacts == 1);
  CHECK_FALSE(pair.on_wall());
  CHECK_FALSE(monomer.on_wall());
  CHECK_THAT(chain.mass, WithinRel(3.0, 1e-14));
  CHECK_THAT(chain.centre_of_mass.x, WithinAbs(1.0, 1e-14));
  CHECK_THAT(chain.radius_of_gyration, WithinRel(std::sqrt(2.0 / 3.0), 1e-14));
  CHECK_THAT(chain.bounding_radius, WithinRel(1.5, 1e-14));
  CHECK_THAT(chain.lowest_gap, WithinAbs(0.0, 1e-14));
  CHECK_THAT(pair.velocity.z, WithinRel(0.3, 1e-14));  // centre-of-mass velocity
  CHECK_THAT(pair.normal_velocity, WithinRel(0.3, 1e-14));
  CHECK_THAT(pair.lowest_gap, WithinRel(4.5, 1e-14));
  CHECK_THAT(monomer.normal_velocity, WithinAbs(0.0, 1e-14));

  const auto distribution = size_distribution(a.fragments);
  CHECK(distribution == std::vector<std::pair<std::size_t, std::size_t>>{{1, 1}, {2, 1}, {3, 1}});
}

TEST_CASE("two separate clusters are two fragments, joined they are one") {
  Particles p;
  for (int k = 0; k < 4; ++k) p.add({static_cast<double>(k), 0.0, 3.0}, 0.5, density);
  for (int k = 0; k < 4; ++k) p.add({static_cast<double>(k), 0.0, 8.0}, 0.5, density);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> contacts{{0, 1}, {1, 2}, {2, 3}, {4, 5}, {5, 6}, {6, 7}};
  CHECK(find_fragments(p, contacts, {}, Wall{}).fragments.size() == 2);
  contacts.emplace_back(3, 4);
  CHECK(find_fragments(p, contacts, {}, Wall{}).fragments.size() == 1);
}

TEST_CASE("the outcome rule: break-up below the share threshold, else stick on the wall, bounce off it") {
  SECTION("stick") {
    const auto c = classify({fragment(95, true, 0.0), fragment(5, false, 0.1)}, true);
    CHECK(c.outcome == ImpactOutcome::stick);
    CHECK_THAT(c.largest_fragment_share, WithinRel(0.95, 1e-14));
  }
  SECTION("bounce") {
    CHECK(classify({fragment(100, false, 0.02)}, true).outcome == ImpactOutcome::bounce);
  }
  SECTION("break-up, whatever the largest fragment does") {
    CHECK(classify({fragment(85, true, 0.0), fragment(15, false, 0.1)}, true).outcome == ImpactOutcome::break_up);
    CHECK(classify({fragment(85, false, 0.1), fragment(15, false, 0.1)}, true).outcome == ImpactOutcome::break_up);
  }
  SECTION("the threshold can be re-applied to the same fragments") {
    const std::vector<Fragment> f{fragment(85, true, 0.0), fragment(15, false, 0.1)};
    CHECK(classify(f, true, 0.9).outcome == ImpactOutcome::break_up);
    CHECK(classify(f, true, 0.8).outcome == ImpactOutcome::stick);
  }
  SECTION("never a guess when the time limit came first") {
    const auto c = classify({fragment(100, true, 0.0)}, false);
    CHECK(c.outcome == ImpactOutcome::undetermined);
    CHECK(to_string(c.outcome) == "undetermined");
  }
  SECTION("a largest fragment off the wall and not moving away is undetermined") {
    CHECK(classify({fragment(100, false, -0.01)}, true).outcome == ImpactOutcome::undetermined);
  }
  CHECK(to_string(ImpactOutcome::break_up) == "break-up");
}

TEST_CASE("the settle judgement") {
  const Vec3 up{0.0, 0.0, 1.0};
  std::vector<Fragment> f{fragment(10, true, 0.0), fragment(1, false, 0.5)};
  f[0].centre_of_mass = {0.0, 0.0, 2.0};
  f[0].bounding_radius = 2.0;
  f[1].centre_of_mass = {0.0, 0.0, 10.0};
  f[1].bounding_radius = 0.5;
  f[1].lowest_gap = 9.5;
  std::vector<Vec3> mean{{0.0, 0.0, 0.0}, {0.0, 0.0, 0.5}};
  const std::vector<double> gap_before{0.0, 9.0};

  CHECK(unsettled_reason(f, mean, gap_before, up, 0.01).empty());

  SECTION("a fragment on the wall that still moves is not at rest") {
    mean[0].z = -0.05;
    CHECK_THAT(unsettled_reason(f, mean, gap_before, up, 0.01), Catch::Matchers::Contains("not at rest"));
  }
  SECTION("a fragment off the wall that comes back") {
    mean[1].z = -0.5;
    f[1].normal_velocity = -0.5;
    CHECK_THAT(unsettled_reason(f, mean, gap_before, up, 0.01), Catch::Matchers::Contains("not moving away"));
  }
  SECTION("fragments on course to meet") {
    f[1].centre_of_mass = {20.0, 0.0, 3.0};
    mean[1] = {-1.0, 0.0, 0.01};
    f[1].normal_velocity = 0.01;
    CHECK_THAT(unsettled_reason(f, mean, {0.0, 9.0}, up, 0.01), Catch::Matchers::Contains("approaching"));
  }
  SECTION("fragments whose paths miss each other") {
    f[1].centre_of_mass = {20.0, 10.0, 3.0};
    mean[1] = {-1.0, 0.0, 0.01};
    f[1].normal_velocity = 0.01;
    CHECK(unsettled_reason(f, mean, {0.0, 9.0}, up, 0.01).empty());
  }
}
