// Reading user clusters from plain and (extended) XYZ text, and rejecting bad input with the line.
#include <catch2/catch.hpp>

#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/io/xyz.hpp"
#include "temporary_path.hpp"

using aerobreak::Cluster;
using aerobreak::Vec3;

namespace {

Cluster read_text(const std::string& text, double default_radius = 0.5) {
  std::istringstream in(text);
  return aerobreak::read_xyz_cluster(in, default_radius, "cluster.xyz");
}

}  // namespace

TEST_CASE("plain XYZ with three columns gets the default radius") {
  const Cluster c = read_text("0 0 0\n1 0 0\n");
  CHECK(c.position == std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}});
  CHECK(c.radius == std::vector<double>{0.5, 0.5});
  CHECK(read_text("0 0 0\n", 2.0).radius == std::vector<double>{2.0});
}

TEST_CASE("plain XYZ reads radii, skips blank and comment lines, tolerates tabs, CRLF and '+'") {
  const Cluster c = read_text("# a dimer\n\n  1.5\t-2 +3e-1 0.25\r\n   # indented comment\n4 5 6\n\n");
  CHECK(c.position == std::vector<Vec3>{{1.5, -2, 0.3}, {4, 5, 6}});
  CHECK(c.radius == std::vector<double>{0.25, 0.5});
}

TEST_CASE("standard XYZ with a count and a comment line is recognised") {
  const Cluster c = read_text("3\nframe 0, written by hand\nC 0 0 0\nC 1 0 0 0.7\nO 0 1 0\n");
  CHECK(c.position == std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  CHECK(c.radius == std::vector<double>{0.5, 0.7, 0.5});
}

TEST_CASE("extended XYZ takes the position and radius columns from Properties") {
  const Cluster c = read_text(
      "2\nLattice=\"10 0 0 0 10 0 0 0 10\" Properties=species:S:1:pos:R:3:velo:R:3:radius:R:1 pbc=\"F F F\"\n"
      "Si 1 2 3 9 9 9 0.4\n"
      "Si 4 5 6 9 9 9 0.6\n");
  CHECK(c.position == std::vector<Vec3>{{1, 2, 3}, {4, 5, 6}});
  CHECK(c.radius == std::vector<double>{0.4, 0.6});

  const Cluster no_radius = read_text("1\nProperties=species:S:1:pos:R:3\nH 7 8 9\n", 1.25);
  CHECK(no_radius.radius == std::vector<double>{1.25});
}

TEST_CASE("malformed XYZ lines are rejected with the line number and content") {
  struct Case {
    std::string text;
    std::string expected;
  };
  const std::vector<Case> cases{
      {"0 0 0\n1 2\n", "cluster.xyz:2: expected 3 or 4 numbers"},
      {"# c\n0 0 0\n1 2 abc\n", "cluster.xyz:3: 'abc' is not a number: '1 2 abc'"},
      {"0 0 0 1 5\n", "cluster.xyz:1: expected 3 or 4 numbers"},
      {"nan 0 0\n", "cluster.xyz:1: 'nan' is not finite"},
      {"0 0 0\n0 inf 0\n", "cluster.xyz:2: 'inf' is not finite"},
      {"0 0 0 -0.5\n", "cluster.xyz:1: radius must be positive: '0 0 0 -0.5'"},
      {"0 0 0 0\n", "cluster.xyz:1: radius must be positive"},
      {"1 2 3x\n", "cluster.xyz:1: '3x' is not a number"},
      {"3\ncomment\nC 0 0 0\nC 1 0 0\n", "line 1 announces 3 particles but only 2 particle lines follow"},
      {"1\ncomment\nC 0 0 0\nC 1 0 0\n", "cluster.xyz:4: more lines than the 1 particles announced on line 1"},
      {"2\ncomment\nC 0 0 0\n0 0 0\n", "cluster.xyz:4: expected 4 or 5 fields"},
      {"1\nProperties=species:S:1:pos:R\nC 0 0 0\n", "cluster.xyz:2: Properties must be name:type:columns triples"},
      {"0\ncomment\n", "cluster.xyz:1: the particle count is zero"},
      {"", "no particles"},
      {"# only a comment\n\n", "no particles"},
  };
  for (const Case& c : cases) {
    INFO(c.text);
    CHECK_THROWS_WITH(read_text(c.text), Catch::Contains(c.expected));
    CHECK_THROWS_AS(read_text(c.text), std::runtime_error);
  }
}

TEST_CASE("reading a missing XYZ file names the file") {
  const aerobreak::test::TemporaryPath missing(".xyz");
  CHECK_THROWS_WITH(aerobreak::read_xyz_cluster(missing.path()), Catch::Contains(missing.path().string()));
}
