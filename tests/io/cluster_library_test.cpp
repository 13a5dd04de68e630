// A cluster library stores many named clusters with their metadata and gives them back
// bit-exactly; anything that is not a library is rejected with the file and cluster named.
#include <catch2/catch.hpp>

#include <hdf5.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/cluster/ballistic_aggregation.hpp"
#include "engine/cluster/cluster_analysis.hpp"
#include "engine/core/version.hpp"
#include "engine/io/cluster_library.hpp"
#include "temporary_path.hpp"

using namespace aerobreak;
using aerobreak::test::TemporaryPath;

namespace {

bool bit_identical(const Cluster& a, const Cluster& b) {
  return a.size() == b.size() && a.radius.size() == b.radius.size() &&
         std::memcmp(a.position.data(), b.position.data(), a.size() * sizeof(Vec3)) == 0 &&
         std::memcmp(a.radius.data(), b.radius.data(), a.radius.size() * sizeof(double)) == 0;
}

ClusterOrigin bcca_origin(std::uint64_t seed) {
  ClusterOrigin origin;
  origin.generator = "bcca";
  origin.parameters = R"({"primaries":64})";
  origin.seed = seed;
  origin.relaxed = true;
  return origin;
}

// Values with all 53 bits of mantissa in use, which a text format would round.
Cluster awkward_cluster() {
  Cluster cluster;
  for (int i = 0; i < 5; ++i) {
    cluster.position.push_back({i / 3.0, -1e-300 * i, 2.5e8 + i / 7.0});
    cluster.radius.push_back(0.5 + i * 1e-16);
  }
  return cluster;
}

long open_hdf5_objects() { return static_cast<long>(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL)); }

}  // namespace

TEST_CASE("clusters stored in a library read back bit-exactly, in the order they were stored") {
  const TemporaryPath file(".h5");
  const std::vector<std::string> names{"zeta", "alpha", "bcca-10", "bcca-2"};
  std::vector<Cluster> clusters{
      ballistic_cluster_cluster_aggregation({64, 1.0, 1.0}, 3),
      ballistic_cluster_cluster_aggregation({17, 1.0, 1.6}, 4),
      awkward_cluster(),
      ballistic_cluster_cluster_aggregation({1, 1.0, 1.0}, 5),
  };
  for (std::size_t i = 0; i < names.size(); ++i) store_cluster(file.path(), names[i], clusters[i], bcca_origin(i));

  CHECK(list_clusters(file.path()) == names);
  for (std::size_t i = 0; i < names.size(); ++i) {
    INFO(names[i]);
    const StoredCluster stored = read_cluster(file.path(), names[i]);
    CHECK(stored.name == names[i]);
    CHECK(bit_identical(stored.cluster, clusters[i]));
  }
  CHECK(open_hdf5_objects() == 0);
}

TEST_CASE("a stored cluster keeps its origin and the measurements the library made") {
  const TemporaryPath file(".h5");
  const Cluster big = ballistic_cluster_cluster_aggregation({512, 1.0, 1.0}, 11);
  ClusterOrigin origin;
  origin.generator = "tunable";
  origin.parameters = R"({"df":1.8,"kf":1.3})";
  origin.seed = 0xFEDCBA9876543210ULL;
  origin.prefactor = 1.3;
  origin.relaxed = false;
  store_cluster(file.path(), "big", big, origin);
  store_cluster(file.path(), "tiny", ballistic_cluster_cluster_aggregation({4, 1.0, 1.0}, 1), bcca_origin(7));

  const ClusterMetadata m = read_cluster(file.path(), "big").metadata;
  CHECK(m.origin.generator == "tunable");
  CHECK(m.origin.parameters == origin.parameters);
  CHECK(m.origin.seed == origin.seed);
  CHECK(m.origin.prefactor == 1.3);
  CHECK_FALSE(m.origin.relaxed);
  CHECK(m.primary_count == 512);
  CHECK(m.radius_of_gyration == radius_of_gyration(big));
  CHECK(m.fractal_dimension == mass_radius_dimension(big));
  CHECK(std::isfinite(m.fractal_dimension));
  CHECK(m.aerobreak_version == std::string(version()));
  CHECK(m.aerobreak_commit == std::string(git_commit()));

  const ClusterMetadata tiny = read_cluster(file.path(), "tiny").metadata;
  CHECK(tiny.origin.relaxed);
  CHECK(tiny.origin.seed == 7);
  CHECK(std::isnan(tiny.origin.prefactor));
  CHECK(std::isnan(tiny.fractal_dimension));
}

TEST_CASE("a stored name is kept unless overwriting is asked for") {
  const TemporaryPath file(".h5");
  const Cluster first = ballistic_cluster_cluster_aggregation({8, 1.0, 1.0}, 1);
  const Cluster second = ballistic_cluster_cluster_aggregation({9, 1.0, 1.0}, 2);
  store_cluster(file.path(), "a", first, bcca_origin(1));
  store_cluster(file.path(), "b", first, bcca_origin(1));

  CHECK_THROWS_WITH(store_cluster(file.path(), "a", second, bcca_origin(2)), Catch::Contains("'a'") &&
                                                                                 Catch::Contains("already stored") &&
                                                                                 Catch::Contains(file.path().string()));
  CHECK(bit_identical(read_cluster(file.path(), "a").cluster, first));

  store_cluster(file.path(), "a", second, bcca_origin(2), ExistingCluster::overwrite);
  CHECK(bit_identical(read_cluster(file.path(), "a").cluster, second));
  CHECK(read_cluster(file.path(), "a").metadata.origin.seed == 2);
  CHECK(list_clusters(file.path()) == std::vector<std::string>{"b", "a"});
}

TEST_CASE("reading a cluster that is not there names it and the file") {
  const TemporaryPath file(".h5");
  store_cluster(file.path(), "present", awkward_cluster(), bcca_origin(1));
  CHECK_THROWS_AS(read_cluster(file.path(), "absent"), std::runtime_error);
  CHECK_THROWS_WITH(read_cluster(file.path(), "absent"), Catch::Contains("'absent'") &&
                                                             Catch::Contains(file.path().string()) &&
                                                             Catch::Contains("'present'"));
  CHECK(open_hdf5_objects() == 0);
}

TEST_CASE("invalid names and clusters are refused before the file is touched") {
  const TemporaryPath file(".h5");
  CHECK_THROWS_WITH(store_cluster(file.path(), "", awkward_cluster(), bcca_origin(1)), Catch::Contains("empty"));
  CHECK_THROWS_WITH(store_cluster(file.path(), "a/b", awkward_cluster(), bcca_origin(1)), Catch::Contains("'/'"));
  CHECK_THROWS_WITH(store_cluster(file.path(), "none", Cluster{}, bcca_origin(1)),
                    Catch::Contains("'none'") && Catch::Contains("without primaries"));
  Cluster bad = awkward_cluster();
  bad.radius[2] = -1.0;
  CHECK_THROWS_WITH(store_cluster(file.path(), "bad", bad, bcca_origin(1)), Catch::Contains("primary 2"));
  bad = awkward_cluster();
  bad.position[1].y = std::nan("");
  CHECK_THROWS_WITH(store_cluster(file.path(), "bad", bad, bcca_origin(1)), Catch::Contains("non-finite"));
  CHECK_FALSE(std::filesystem::exists(file.path()));
}

TEST_CASE("files that are not cluster libraries are rejected with their name") {
  SECTION("a missing file") {
    const TemporaryPath missing(".h5");
    CHECK_THROWS_WITH(list_clusters(missing.path()),
                      Catch::Contains(missing.path().string()) && Catch::Contains("no such file"));
    CHECK_THROWS_AS(read_cluster(missing.path(), "x"), std::runtime_error);
  }
  SECTION("a text file") {
    const TemporaryPath text(".h5");
    std::ofstream(text.path()) << "0 0 0 0.5\n1 0 0 0.5\n";
    CHECK_FALSE(is_hdf5_file(text.path()));
    CHECK_THROWS_WITH(list_clusters(text.path()), Catch::Contains("not an aerobreak cluster library"));
    CHECK_THROWS_WITH(store_cluster(text.path(), "x", awkward_cluster(), bcca_origin(1)),
                      Catch::Contains("not an aerobreak cluster library") && Catch::Contains("'x'"));
  }
  SECTION("another HDF5 file") {
    const TemporaryPath plain(".h5");
    H5Fclose(H5Fcreate(plain.path().c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT));
    CHECK(is_hdf5_file(plain.path()));
    CHECK_THROWS_WITH(list_clusters(plain.path()),
                      Catch::Contains("not an aerobreak cluster library") && Catch::Contains(plain.path().string()));
    CHECK_THROWS_AS(store_cluster(plain.path(), "x", awkward_cluster(), bcca_origin(1)), std::runtime_error);
  }
  SECTION("a library cut short") {
    const TemporaryPath file(".h5");
    store_cluster(file.path(), "x", ballistic_cluster_cluster_aggregation({256, 1.0, 1.0}, 1), bcca_origin(1));
    std::filesystem::resize_file(file.path(), std::filesystem::file_size(file.path()) / 2);
    CHECK_THROWS_WITH(read_cluster(file.path(), "x"), Catch::Contains(file.path().string()));
  }
  CHECK(open_hdf5_objects() == 0);
}
