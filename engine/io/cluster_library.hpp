#pragma once
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "engine/cluster/cluster.hpp"

namespace aerobreak {

// A cluster library: one HDF5 file holding many named clusters, the store from which impact cases
// take their clusters (docs/ARCHITECTURE.md, "The engine": bulk arrays go to HDF5).
//
// Layout (format version 1.0):
//   /aerobreak                  attributes format = "aerobreak cluster library",
//                               format_version = [1, 0] (int32), creator = aerobreak version
//   /clusters/<name>/position   float64 [N, 3]
//   /clusters/<name>/radius     float64 [N]
//   /clusters/<name>            attributes generator (string), parameters (JSON text), seed
//                               (uint64), relaxed (uint8, 0 or 1), prefactor (float64, NaN if not
//                               known), measured primary_count (uint64), radius_of_gyration and
//                               fractal_dimension (float64; mass-radius, NaN when the cluster is too
//                               small), aerobreak_version and aerobreak_commit (strings)
// Clusters are listed in the order they were stored (an overwritten cluster moves to the end).
// Overwriting a cluster does not shrink the file (HDF5 does not reuse the space; h5repack does).

// How a cluster was made: what its producer knows and the library cannot measure.
struct ClusterOrigin {
  std::string generator;                                        // e.g. "bcca", "tunable", "xyz" (imported)
  std::string parameters = "{}";                                // the generator's parameters as a JSON object, verbatim
  std::uint64_t seed = 0;                                       // the seed that reproduces the cluster with `generator`
  double prefactor = std::numeric_limits<double>::quiet_NaN();  // k_f of N = k_f (Rg/a)^D_f, if fixed
  bool relaxed = false;                                         // brought to mechanical equilibrium (relax_cluster)
};

// Everything stored with a cluster: its origin, what the library measured when storing it, and
// the aerobreak that wrote it.
struct ClusterMetadata {
  ClusterOrigin origin;
  std::size_t primary_count = 0;
  double radius_of_gyration = 0.0;  // of the centres as point masses ~ r^3 (cluster_analysis.hpp)
  double fractal_dimension = std::numeric_limits<double>::quiet_NaN();  // mass-radius dimension
  std::string aerobreak_version;
  std::string aerobreak_commit;
};

struct StoredCluster {
  std::string name;
  Cluster cluster;
  ClusterMetadata metadata;
};

enum class ExistingCluster { reject, overwrite };

// Stores `cluster` as `name`, creating the library file if it does not exist. A name is one
// non-empty HDF5 link name: no '/', not "." . Throws std::runtime_error naming the file and the
// cluster for an invalid name, an empty cluster, radii and positions of different lengths or
// non-finite values, a name already stored (with ExistingCluster::reject), a file that is not a
// cluster library, or any HDF5 failure.
void store_cluster(const std::filesystem::path& library, const std::string& name, const Cluster& cluster,
                   const ClusterOrigin& origin, ExistingCluster existing = ExistingCluster::reject);

// Names of the stored clusters, in the order they were stored.
std::vector<std::string> list_clusters(const std::filesystem::path& library);

// One stored cluster, bit-exact as written. Throws std::runtime_error naming the file and the
// cluster if it is missing or malformed.
StoredCluster read_cluster(const std::filesystem::path& library, const std::string& name);

// Whether `path` is an HDF5 file (by its signature), so that callers can tell a library from a
// text file; false for a missing or unreadable file.
bool is_hdf5_file(const std::filesystem::path& path);

}  // namespace aerobreak
