// The H5MD file carries the groups, attributes and dataset shapes of the H5MD 1.1 specification,
// checked with the plain HDF5 API rather than with the project's own reader.
#include <catch2/catch.hpp>

#include <hdf5.h>

#include <cstdint>
#include <string>
#include <vector>

#include "engine/io/h5md_writer.hpp"
#include "temporary_path.hpp"

using aerobreak::H5mdTrajectoryWriter;
using aerobreak::Particles;
using aerobreak::test::TemporaryPath;

namespace {

std::vector<long long> integer_attribute(hid_t file, const char* object, const char* name) {
  const hid_t attribute = H5Aopen_by_name(file, object, name, H5P_DEFAULT, H5P_DEFAULT);
  REQUIRE(attribute >= 0);
  const hid_t space = H5Aget_space(attribute);
  std::vector<long long> values(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
  CHECK(H5Aread(attribute, H5T_NATIVE_LLONG, values.data()) >= 0);
  H5Sclose(space);
  H5Aclose(attribute);
  return values;
}

// A fixed-length string attribute (H5MD mandates fixed length), scalar or array.
std::vector<std::string> fixed_string_attribute(hid_t file, const char* object, const char* name) {
  const hid_t attribute = H5Aopen_by_name(file, object, name, H5P_DEFAULT, H5P_DEFAULT);
  REQUIRE(attribute >= 0);
  const hid_t type = H5Aget_type(attribute);
  CHECK(H5Tget_class(type) == H5T_STRING);
  CHECK(H5Tis_variable_str(type) == 0);
  const std::size_t size = H5Tget_size(type);
  const hid_t space = H5Aget_space(attribute);
  const auto count = static_cast<std::size_t>(H5Sget_simple_extent_npoints(space));
  std::vector<char> packed(count * size);
  CHECK(H5Aread(attribute, type, packed.data()) >= 0);
  std::vector<std::string> values;
  for (std::size_t i = 0; i < count; ++i) {
    const std::string raw(&packed[i * size], size);
    values.push_back(raw.substr(0, raw.find('\0')));
  }
  H5Sclose(space);
  H5Tclose(type);
  H5Aclose(attribute);
  return values;
}

struct Extent {
  std::vector<hsize_t> dims;
  std::vector<hsize_t> max_dims;
};

Extent dataset_extent(hid_t file, const char* path) {
  const hid_t dataset = H5Dopen2(file, path, H5P_DEFAULT);
  REQUIRE(dataset >= 0);
  const hid_t space = H5Dget_space(dataset);
  Extent extent;
  extent.dims.resize(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)));
  extent.max_dims.resize(extent.dims.size());
  H5Sget_simple_extent_dims(space, extent.dims.data(), extent.max_dims.data());
  H5Sclose(space);
  H5Dclose(dataset);
  return extent;
}

template <class T>
std::vector<T> dataset_values(hid_t file, const char* path, hid_t memory_type, std::size_t count) {
  const hid_t dataset = H5Dopen2(file, path, H5P_DEFAULT);
  REQUIRE(dataset >= 0);
  std::vector<T> values(count);
  CHECK(H5Dread(dataset, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) >= 0);
  H5Dclose(dataset);
  return values;
}

bool exists(hid_t file, const char* path) { return H5Lexists(file, path, H5P_DEFAULT) > 0; }

Particles particles(std::size_t n) {
  Particles p;
  for (std::size_t i = 0; i < n; ++i) p.add({1.0 * i, 0.0, 0.0}, 0.5, 1.0);
  return p;
}

}  // namespace

TEST_CASE("H5MD file has the metadata, box and element layout of H5MD 1.1") {
  const TemporaryPath path(".h5");
  constexpr std::size_t n = 4;
  constexpr hsize_t frames = 3;
  {
    H5mdTrajectoryWriter writer(path.path(), "1.2.3", {.velocities = true, .forces = false, .author = "A. Tester"});
    for (hsize_t f = 0; f < frames; ++f) {
      const auto step = static_cast<std::int64_t>(10 * f);
      const double time = 0.5 * static_cast<double>(f);
      writer.append(particles(n), step, time);
      writer.append_observable("kinetic_energy", step, time, 2.0 * static_cast<double>(f));
    }
  }

  const hid_t file = H5Fopen(path.path().c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  REQUIRE(file >= 0);

  CHECK(integer_attribute(file, "h5md", "version") == std::vector<long long>{1, 1});
  CHECK(fixed_string_attribute(file, "h5md/author", "name") == std::vector<std::string>{"A. Tester"});
  CHECK(fixed_string_attribute(file, "h5md/creator", "name") == std::vector<std::string>{"aerobreak"});
  CHECK(fixed_string_attribute(file, "h5md/creator", "version") == std::vector<std::string>{"1.2.3"});

  CHECK(integer_attribute(file, "particles/all/box", "dimension") == std::vector<long long>{3});
  CHECK(fixed_string_attribute(file, "particles/all/box", "boundary") ==
        std::vector<std::string>{"none", "none", "none"});

  const Extent position = dataset_extent(file, "particles/all/position/value");
  CHECK(position.dims == std::vector<hsize_t>{frames, n, 3});
  CHECK(position.max_dims == std::vector<hsize_t>{H5S_UNLIMITED, n, 3});
  CHECK(dataset_extent(file, "particles/all/velocity/value").dims == std::vector<hsize_t>{frames, n, 3});
  CHECK(dataset_extent(file, "particles/all/radius/value").dims == std::vector<hsize_t>{frames, n});
  CHECK_FALSE(exists(file, "particles/all/force"));

  const std::vector<long long> steps{0, 10, 20};
  for (const char* element : {"position", "velocity", "radius"}) {
    INFO(element);
    const std::string group = std::string("particles/all/") + element;
    CHECK(dataset_values<long long>(file, (group + "/step").c_str(), H5T_NATIVE_LLONG, frames) == steps);
    CHECK(dataset_values<double>(file, (group + "/time").c_str(), H5T_NATIVE_DOUBLE, frames) ==
          std::vector<double>{0.0, 0.5, 1.0});
  }

  CHECK(dataset_extent(file, "particles/all/id").dims == std::vector<hsize_t>{n});
  CHECK(dataset_values<long long>(file, "particles/all/id", H5T_NATIVE_LLONG, n) == std::vector<long long>{0, 1, 2, 3});

  CHECK(dataset_extent(file, "observables/kinetic_energy/value").dims == std::vector<hsize_t>{frames});
  CHECK(dataset_values<double>(file, "observables/kinetic_energy/value", H5T_NATIVE_DOUBLE, frames) ==
        std::vector<double>{0.0, 2.0, 4.0});
  CHECK(dataset_values<long long>(file, "observables/kinetic_energy/step", H5T_NATIVE_LLONG, frames) == steps);

  H5Fclose(file);
}
