// Clusters in files of either kind (engine/io/cluster_files.hpp): read by content, written by name,
// converted between a library and XYZ files with their origin kept or recorded.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>
#include <stdexcept>

#include "engine/io/cluster_files.hpp"
#include "engine/io/xyz.hpp"
#include "temporary_path.hpp"

using namespace aerobreak;
using aerobreak::test::TemporaryPath;

namespace {

Cluster three_in_a_row() {
  Cluster cluster;
  for (int i = 0; i < 3; ++i) {
    cluster.position.push_back({static_cast<double>(i), 0.0, 0.0});
    cluster.radius.push_back(0.5);
  }
  return cluster;
}

}  // namespace

TEST_CASE("a name ending in .h5 or .hdf5, in any case, is a library, any other an XYZ file") {
  CHECK(names_cluster_library("a/clusters.h5"));
  CHECK(names_cluster_library("clusters.HDF5"));
  CHECK_FALSE(names_cluster_library("cluster.xyz"));
  CHECK_FALSE(names_cluster_library("h5"));
}

TEST_CASE("an XYZ file converted into a library and back keeps its cluster, with origin xyz and its source") {
  const TemporaryPath text(".xyz"), library(".h5"), again(".xyz");
  write_xyz_cluster(text.path(), three_in_a_row());
  CHECK(convert_cluster_file(text.path(), library.path(), "", ExistingCluster::reject) == 1);
  const auto stored = read_cluster_file(library.path());
  REQUIRE(stored.size() == 1);
  CHECK(stored[0].name == "file");  // the XYZ file's name without its extension
  REQUIRE(stored[0].metadata);
  CHECK(stored[0].metadata->origin.generator == "xyz");
  CHECK(nlohmann::json::parse(stored[0].metadata->origin.parameters).at("source") == text.path().string());
  CHECK(convert_cluster_file(library.path(), again.path(), "file", ExistingCluster::reject) == 1);
  const auto back = read_cluster_file(again.path());
  REQUIRE(back.size() == 1);
  CHECK(back[0].cluster.position == stored[0].cluster.position);
  CHECK(back[0].cluster.radius == stored[0].cluster.radius);
  CHECK_FALSE(back[0].metadata);
}

TEST_CASE("reading and converting refuse what cannot be done, naming the file") {
  const TemporaryPath text(".xyz"), library(".h5"), out(".xyz");
  CHECK_THROWS_WITH(read_cluster_file(text.path()), Catch::Contains("no such file"));
  write_xyz_cluster(text.path(), three_in_a_row());
  CHECK_THROWS_WITH(read_cluster_file(text.path(), "c"), Catch::Contains("not an HDF5 file"));
  convert_cluster_file(text.path(), library.path(), "c", ExistingCluster::reject);
  CHECK_THROWS_WITH(convert_cluster_file(library.path(), out.path(), "", ExistingCluster::reject),
                    Catch::Contains("needs --name") && Catch::Contains("holds: c"));
  CHECK_THROWS(convert_cluster_file(text.path(), library.path(), "c", ExistingCluster::reject));
  CHECK(convert_cluster_file(text.path(), library.path(), "c", ExistingCluster::overwrite) == 1);
}
