// H5MD trajectories read back exactly as written, and the writer rejects what H5MD cannot hold.
#include <catch2/catch.hpp>

#include <hdf5.h>

#include <cstdint>
#include <stdexcept>
#include <vector>

#include "engine/io/h5md_reader.hpp"
#include "engine/io/h5md_writer.hpp"
#include "temporary_path.hpp"

using aerobreak::H5mdFrame;
using aerobreak::H5mdTrajectoryWriter;
using aerobreak::Particles;
using aerobreak::Vec3;
using aerobreak::test::TemporaryPath;

namespace {

// Particles whose values differ per frame and include numbers that do not survive a lossy format.
Particles frame_particles(std::size_t n, int frame) {
  Particles p;
  for (std::size_t i = 0; i < n; ++i) {
    const double k = static_cast<double>(i) + 10.0 * frame;
    p.add({0.1 * k, k / 3.0, -2.5e8 + k}, 0.5 + 1e-17 * k + 0.01 * frame, 1.0);
    p.velocity.back() = {1e-17 * (k + 1), -k / 7.0, 1.0 / 3.0};
    p.force.back() = {k * 1e3, -0.1, 2.0 / 3.0 * k};
  }
  return p;
}

long open_hdf5_objects() { return static_cast<long>(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL)); }

}  // namespace

TEST_CASE("H5MD trajectory frames read back bit-exactly") {
  const TemporaryPath file(".h5");
  const std::vector<std::int64_t> steps{0, 100, 250};
  const std::vector<double> times{0.0, 0.1, 1.0 / 3.0};
  const std::size_t n = 5;
  {
    H5mdTrajectoryWriter writer(file.path(), "0.1.0-test", {.velocities = true, .forces = true});
    for (int f = 0; f < 3; ++f) writer.append(frame_particles(n, f), steps[f], times[f]);
    CHECK(writer.frame_count() == 3);
  }

  REQUIRE(aerobreak::h5md_frame_count(file.path()) == 3);
  for (int f = 0; f < 3; ++f) {
    const Particles expected = frame_particles(n, f);
    const H5mdFrame frame = aerobreak::read_h5md_frame(file.path(), static_cast<std::size_t>(f));
    CHECK(frame.step == steps[f]);
    REQUIRE(frame.time.has_value());
    CHECK(*frame.time == times[f]);
    CHECK(frame.position == expected.position);
    CHECK(frame.velocity == expected.velocity);
    CHECK(frame.force == expected.force);
    CHECK(frame.radius == expected.radius);
  }
  CHECK(open_hdf5_objects() == 0);
}

TEST_CASE("H5MD elements left out by the options are absent on reading") {
  const TemporaryPath file(".h5");
  {
    H5mdTrajectoryWriter writer(file.path(), "test", {.velocities = false, .forces = false});
    writer.append(frame_particles(3, 0), 7, 0.5);
  }
  const H5mdFrame frame = aerobreak::read_h5md_frame(file.path(), 0);
  CHECK(frame.position == frame_particles(3, 0).position);
  CHECK(frame.radius == frame_particles(3, 0).radius);
  CHECK(frame.velocity.empty());
  CHECK(frame.force.empty());
}

TEST_CASE("H5MD writer keeps the particle count of the first frame") {
  const TemporaryPath file(".h5");
  H5mdTrajectoryWriter writer(file.path(), "test");
  writer.append(frame_particles(4, 0), 0, 0.0);
  CHECK_THROWS_AS(writer.append(frame_particles(5, 1), 1, 0.1), std::invalid_argument);
  writer.append(frame_particles(4, 1), 1, 0.1);
  writer.close();
  CHECK(aerobreak::h5md_frame_count(file.path()) == 2);
}

TEST_CASE("H5MD writer rejects a frame without particles") {
  const TemporaryPath file(".h5");
  H5mdTrajectoryWriter writer(file.path(), "test");
  CHECK_THROWS_AS(writer.append(Particles{}, 0, 0.0), std::invalid_argument);
}

TEST_CASE("H5MD writer rejects steps that do not increase") {
  const TemporaryPath file(".h5");
  H5mdTrajectoryWriter writer(file.path(), "test");
  writer.append(frame_particles(2, 0), 10, 0.0);
  CHECK_THROWS_AS(writer.append(frame_particles(2, 1), 10, 0.1), std::invalid_argument);
  writer.append_observable("energy", 5, 0.0, 1.0);
  CHECK_THROWS_AS(writer.append_observable("energy", 4, 0.0, 1.0), std::invalid_argument);
}

TEST_CASE("H5MD writer rejects observable names that are not a single group name") {
  const TemporaryPath file(".h5");
  H5mdTrajectoryWriter writer(file.path(), "test");
  CHECK_THROWS_AS(writer.append_observable("", 0, 0.0, 1.0), std::invalid_argument);
  CHECK_THROWS_AS(writer.append_observable("a/b", 0, 0.0, 1.0), std::invalid_argument);
}

TEST_CASE("H5MD writer refuses to append after close") {
  const TemporaryPath file(".h5");
  H5mdTrajectoryWriter writer(file.path(), "test");
  writer.close();
  writer.close();
  CHECK_THROWS_AS(writer.append(frame_particles(2, 0), 0, 0.0), std::logic_error);
  CHECK(open_hdf5_objects() == 0);
}

TEST_CASE("H5MD writer reports an unwritable path as a runtime_error naming it") {
  const std::string path = "/nonexistent-aerobreak-directory/trajectory.h5";
  CHECK_THROWS_WITH(H5mdTrajectoryWriter(path, "test"), Catch::Contains(path));
  CHECK_THROWS_AS(H5mdTrajectoryWriter(path, "test"), std::runtime_error);
  CHECK(open_hdf5_objects() == 0);
}

TEST_CASE("H5MD reader rejects missing files, other HDF5 files and frames past the end") {
  const TemporaryPath missing(".h5");
  CHECK_THROWS_AS(aerobreak::h5md_frame_count(missing.path()), std::runtime_error);

  const TemporaryPath plain(".h5");
  H5Fclose(H5Fcreate(plain.path().c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT));
  CHECK_THROWS_WITH(aerobreak::read_h5md_frame(plain.path(), 0), Catch::Contains("not an H5MD file"));

  const TemporaryPath file(".h5");
  { H5mdTrajectoryWriter(file.path(), "test").append(frame_particles(2, 0), 0, 0.0); }
  CHECK_THROWS_AS(aerobreak::read_h5md_frame(file.path(), 1), std::out_of_range);
  CHECK(open_hdf5_objects() == 0);
}
