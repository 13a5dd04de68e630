// Writing clusters and frames as text that reads back to the identical doubles.
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/io/xyz.hpp"
#include "temporary_path.hpp"

using aerobreak::Cluster;
using aerobreak::Particles;
using aerobreak::test::TemporaryPath;

namespace {

// Values whose decimal forms need all 17 significant digits, or are tiny, huge or negative.
Cluster awkward_cluster() {
  Cluster c;
  c.position = {{0.1, 1.0 / 3.0, 1e-17}, {-2.5e8, 2.0 / 3.0, -0.0}, {5e-324, 1.7976931348623157e308, -1e-300}};
  c.radius = {0.5, 1.0 / 7.0, 1e-17};
  return c;
}

}  // namespace

TEST_CASE("XYZ cluster round trip through a stream is bit-exact") {
  const Cluster written = awkward_cluster();
  std::stringstream text;
  aerobreak::write_xyz_cluster(text, written);
  const Cluster read = aerobreak::read_xyz_cluster(text);
  CHECK(read.position == written.position);
  CHECK(read.radius == written.radius);
}

TEST_CASE("XYZ cluster round trip through a file is bit-exact") {
  const TemporaryPath file(".xyz");
  const Cluster written = awkward_cluster();
  aerobreak::write_xyz_cluster(file.path(), written);
  const Cluster read = aerobreak::read_xyz_cluster(file.path());
  CHECK(read.position == written.position);
  CHECK(read.radius == written.radius);
}

TEST_CASE("writing an XYZ cluster to an unwritable path throws") {
  const std::string path = "/nonexistent-aerobreak-directory/cluster.xyz";
  CHECK_THROWS_WITH(aerobreak::write_xyz_cluster(path, awkward_cluster()), Catch::Contains(path));
}

TEST_CASE("XYZ frames are standard extended XYZ, appendable, and read back exactly") {
  Particles p;
  p.add({0.1, 0.2, 1.0 / 3.0}, 0.5, 1.0);
  p.add({-2.5e8, 1e-17, 0.0}, 0.75, 1.0);
  std::stringstream two_frames;
  aerobreak::write_xyz_frame(two_frames, p, "Time=0.5");
  aerobreak::write_xyz_frame(two_frames, p);

  std::vector<std::string> lines;
  for (std::string line; std::getline(two_frames, line);) lines.push_back(line);
  REQUIRE(lines.size() == 8);
  CHECK(lines[0] == "2");
  CHECK(lines[1] == "Properties=species:S:1:pos:R:3:radius:R:1 Time=0.5");
  CHECK(lines[2].rfind("P ", 0) == 0);
  CHECK(lines[4] == "2");
  CHECK(lines[5] == "Properties=species:S:1:pos:R:3:radius:R:1");

  std::istringstream first_frame(lines[0] + "\n" + lines[1] + "\n" + lines[2] + "\n" + lines[3] + "\n");
  const Cluster read = aerobreak::read_xyz_cluster(first_frame);
  CHECK(read.position == p.position);
  CHECK(read.radius == p.radius);
}

TEST_CASE("an XYZ frame comment must stay on one line") {
  Particles p;
  p.add({0, 0, 0}, 0.5, 1.0);
  std::ostringstream out;
  CHECK_THROWS_AS(aerobreak::write_xyz_frame(out, p, "two\nlines"), std::invalid_argument);
}

TEST_CASE("writing to a failed stream throws") {
  std::ofstream closed;
  CHECK_THROWS_AS(aerobreak::write_xyz_cluster(closed, awkward_cluster()), std::runtime_error);
}
