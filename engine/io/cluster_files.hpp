#pragma once
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "engine/cluster/cluster.hpp"
#include "engine/io/cluster_library.hpp"

// Clusters in files of either kind: a cluster library (HDF5, cluster_library.hpp) or an XYZ text
// file (xyz.hpp), told apart by their content when read and by the name when written.
namespace aerobreak {

// One cluster from a file, with its library metadata when it came from a library.
struct NamedCluster {
  std::string name;
  Cluster cluster;
  std::optional<ClusterMetadata> metadata;
};

// Whether a file to be written is a cluster library: its name ends in .h5 or .hdf5 (any case);
// any other name is an XYZ file.
bool names_cluster_library(const std::filesystem::path& path);

// The clusters of `path`: of a library, the one called `name`, or all of them for an empty name;
// of an XYZ file its one cluster, named after the file (a `name` is refused: it selects a
// library's cluster). Throws std::runtime_error for a missing file, an empty XYZ file, or a name
// the library does not hold.
std::vector<NamedCluster> read_cluster_file(const std::filesystem::path& path, const std::string& name = "");

// Copies the clusters of `input` into `output` (a library if names_cluster_library, else an XYZ
// file, replaced if it exists). From a library, `name` chooses one cluster (all for an empty name;
// an XYZ output needs one); from an XYZ file it names the cluster stored (default: the file name
// without extension). Library entries keep their origin; an XYZ file's cluster is stored with
// origin "xyz" and its source file. Returns how many clusters were written.
std::size_t convert_cluster_file(const std::filesystem::path& input, const std::filesystem::path& output,
                                 const std::string& name, ExistingCluster existing);

}  // namespace aerobreak
