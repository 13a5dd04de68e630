// Fragments (connected components of the contact graph), the outcome rule (by what leaves the
// wall) and the settle judgements on constructed states with known answers.
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

namespace {

// `primaries` primaries of `mass_each`, on the wall at rest or off it moving away.
FragmentFate fate(std::size_t primaries, bool on_wall, double mass_each = 1.0) {
  return {primaries, mass_each * static_cast<double>(primaries), on_wall, on_wall ? 0.0 : 0.1, on_wall ? 0.0 : 0.1};
}

constexpr bool settled = true;

}  // namespace

TEST_CASE("the outcome rule decides by what leaves the wall") {
  SECTION("stick: nothing leaves the wall") {
    const Classification c = classify({fate(100, true)}, settled);
    CHECK(c.outcome == ImpactOutcome::stick);
    CHECK_FALSE(c.fractured_on_wall);
    CHECK(c.retained_mass_fraction == 1.0);
    CHECK(c.reentrained_mass_fraction == 0.0);
    CHECK(c.reentrained.empty());
    CHECK(c.largest_reentrained_share == 0.0);
  }
  SECTION("stick: a deposit cracked into pieces on the wall is still a stick, fractured on the wall") {
    // The former rule called this a break-up: the largest piece holds 60 % of the primaries.
    const Classification c = classify({fate(60, true), fate(30, true), fate(10, true)}, settled);
    CHECK(c.outcome == ImpactOutcome::stick);
    CHECK(c.fractured_on_wall);
    CHECK(c.retained_mass_fraction == 1.0);
    CHECK_THAT(c.largest_fragment_share, WithinRel(0.6, 1e-14));
  }
  SECTION("bounce: the heaviest fragment off the wall holds at least the bounce share; debris stays behind") {
    const Classification c = classify({fate(95, false), fate(5, true)}, settled);
    CHECK(c.outcome == ImpactOutcome::bounce);
    CHECK_FALSE(c.fractured_on_wall);
    CHECK_THAT(c.retained_mass_fraction, WithinRel(0.05, 1e-14));
    CHECK_THAT(c.reentrained_mass_fraction, WithinRel(0.95, 1e-14));
    CHECK(c.reentrained == std::vector<std::size_t>{0});
  }
  SECTION("bounce: debris may also leave, in pieces of its own") {
    const Classification c = classify({fate(92, false), fate(5, false), fate(3, true)}, settled);
    CHECK(c.outcome == ImpactOutcome::bounce);
    CHECK_THAT(c.reentrained_mass_fraction, WithinRel(0.97, 1e-14));
    CHECK_THAT(c.largest_reentrained_share, WithinRel(0.92, 1e-14));
    CHECK(c.reentrained == std::vector<std::size_t>{0, 1});
  }
  SECTION("break-up: mass leaves the wall in pieces") {
    const Classification c = classify({fate(50, true), fate(30, false), fate(20, false)}, settled);
    CHECK(c.outcome == ImpactOutcome::break_up);
    CHECK_THAT(c.retained_mass_fraction, WithinRel(0.5, 1e-14));
    CHECK_THAT(c.largest_reentrained_share, WithinRel(0.3, 1e-14));
    CHECK(c.reentrained == std::vector<std::size_t>{1, 2});
  }
  SECTION("break-up: one monomer leaving a deposit is mass leaving the wall") {
    // Under the former rule a stick: the largest fragment holds 99 % of the primaries.
    const Classification c = classify({fate(99, true), fate(1, false)}, settled);
    CHECK(c.outcome == ImpactOutcome::break_up);
    CHECK_THAT(c.retained_mass_fraction, WithinRel(0.99, 1e-14));
    CHECK_FALSE(c.fractured_on_wall);
  }
  SECTION("break-up: the whole cluster leaves, but no piece holds the bounce share") {
    const Classification c = classify({fate(85, false), fate(15, false)}, settled);
    CHECK(c.outcome == ImpactOutcome::break_up);
    CHECK(c.retained_mass_fraction == 0.0);
    CHECK(c.reentrained_mass_fraction == 1.0);
  }
  SECTION("shares are shares of the mass, not of the primaries") {
    // 10 heavy primaries leave with 90 % of the mass; 90 light ones, 10 % of it, stay.
    const Classification c = classify({fate(90, true, 1.0 / 90.0), fate(10, false, 0.9)}, settled);
    CHECK(c.outcome == ImpactOutcome::bounce);
    CHECK_THAT(c.largest_reentrained_share, WithinRel(0.9, 1e-14));
    CHECK_THAT(c.largest_fragment_share, WithinRel(0.9, 1e-14));
  }
  SECTION("the bounce share is the case's threshold, and is reached at equality") {
    const std::vector<FragmentFate> f{fate(85, false), fate(15, true)};
    CHECK(classify(f, settled, {0.9}).outcome == ImpactOutcome::break_up);
    CHECK(classify(f, settled, {0.85}).outcome == ImpactOutcome::bounce);
    CHECK(classify(f, settled, {0.8}).outcome == ImpactOutcome::bounce);
    CHECK_THROWS_AS(classify(f, settled, {0.5}), std::invalid_argument);
    CHECK_THROWS_AS(classify(f, settled, {1.2}), std::invalid_argument);
  }
  SECTION("never a guess when the time limit came first; the fractions are those of the last state") {
    const Classification c = classify({fate(70, true), fate(30, false)}, false);
    CHECK(c.outcome == ImpactOutcome::undetermined);
    CHECK(to_string(c.outcome) == "undetermined");
    CHECK_THAT(c.retained_mass_fraction, WithinRel(0.7, 1e-14));
  }
  CHECK(to_string(ImpactOutcome::break_up) == "break-up");
}

TEST_CASE("the outcome rule reads a fragment's place and velocity from the fragment analysis") {
  const Scene s = scene();
  const FragmentAnalysis a = find_fragments(s.p, s.contacts, s.wall_contacts, Wall{});
  std::vector<Vec3> velocity;
  for (const Fragment& f : a.fragments) velocity.push_back(f.velocity);
  const std::vector<FragmentFate> f = fates_of(a.fragments, velocity, {0.0, 0.0, 2.0});
  REQUIRE(f.size() == 3);
  CHECK(f[0].on_wall);
  CHECK_FALSE(f[1].on_wall);
  CHECK(f[1].primaries == 2);
  CHECK_THAT(f[1].normal_velocity, WithinRel(0.3, 1e-14));
  CHECK_THAT(f[2].speed, WithinRel(1.0, 1e-14));
  const Classification c = classify(f, settled);
  CHECK(c.outcome == ImpactOutcome::break_up);
  CHECK_THAT(c.retained_mass_fraction, WithinRel(0.5, 1e-14));
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

TEST_CASE("the outcome-fixed judgement: a break-up that can no longer become anything else") {
  const Vec3 up{0.0, 0.0, 1.0};
  // A deposit of 50 primaries at rest on the wall, two pieces of 30 and 20 flying apart above it.
  std::vector<Fragment> f{fragment(50, true, 0.0), fragment(30, false, 0.5), fragment(20, false, 0.5)};
  f[0].centre_of_mass = {0.0, 0.0, 2.0};
  f[0].bounding_radius = 3.0;
  f[1].centre_of_mass = {-10.0, 0.0, 12.0};
  f[1].bounding_radius = 2.0;
  f[1].lowest_gap = 9.5;
  f[2].centre_of_mass = {10.0, 0.0, 12.0};
  f[2].bounding_radius = 2.0;
  f[2].lowest_gap = 9.5;
  std::vector<Vec3> mean{{0.0, 0.0, 0.0}, {-0.2, 0.0, 0.5}, {0.2, 0.0, 0.5}};
  const std::vector<double> gap_before{0.0, 9.0, 9.0};
  const OutcomeThresholds thresholds{0.9};

  CHECK(outcome_open_reason(f, mean, gap_before, up, 0.01, thresholds).empty());

  SECTION("what the settle judgement refuses, this one refuses too") {
    mean[0].z = -0.05;
    CHECK_THAT(outcome_open_reason(f, mean, gap_before, up, 0.01, thresholds),
               Catch::Matchers::Contains("not at rest"));
  }
  SECTION("pieces in flight on course to meet") {
    mean[1] = {0.2, 0.0, 0.5};
    mean[2] = {-0.2, 0.0, 0.5};
    CHECK_THAT(outcome_open_reason(f, mean, gap_before, up, 0.01, thresholds),
               Catch::Matchers::Contains("approaching"));
  }
  SECTION("a stick or a bounce is not fixed by this rule") {
    const std::vector<Fragment> deposit{f[0]};
    CHECK_THAT(outcome_open_reason(deposit, {mean[0]}, {0.0}, up, 0.01, thresholds),
               Catch::Matchers::Contains("stick"));
    std::vector<Fragment> bouncing{fragment(95, false, 0.5), fragment(5, true, 0.0)};
    bouncing[0].centre_of_mass = {0.0, 0.0, 12.0};
    bouncing[0].lowest_gap = 9.5;
    bouncing[1].centre_of_mass = {20.0, 0.0, 0.5};
    CHECK_THAT(outcome_open_reason(bouncing, {{0.0, 0.0, 0.5}, {}}, {9.0, 0.0}, up, 0.01, thresholds),
               Catch::Matchers::Contains("bounce"));
  }
  SECTION("a deposit heavy enough to leave later as a bounce keeps the outcome open") {
    f[0].size = 950;
    f[0].mass = 950.0;
    CHECK_THAT(outcome_open_reason(f, mean, gap_before, up, 0.01, thresholds),
               Catch::Matchers::Contains("could still leave as a bounce"));
  }
}
