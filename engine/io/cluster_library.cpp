#include "engine/io/cluster_library.hpp"

#include <hdf5.h>

#include <cmath>
#include <stdexcept>
#include <type_traits>

#include "engine/cluster/cluster_analysis.hpp"
#include "engine/core/version.hpp"
#include "engine/io/hdf5_attributes.hpp"
#include "engine/io/hdf5_datasets.hpp"
#include "engine/io/hdf5_handle.hpp"

namespace aerobreak {

static_assert(sizeof(Vec3) == 3 * sizeof(double) && std::is_standard_layout_v<Vec3>,
              "Vec3 arrays are stored as contiguous [N][3] doubles");

namespace {

constexpr const char* kFormatName = "aerobreak cluster library";
constexpr std::int32_t kFormatMajor = 1;
constexpr std::int32_t kFormatMinor = 0;
constexpr const char* kClustersGroup = "clusters";
constexpr std::size_t kNamesShownWhenMissing = 10;

std::string describe(const std::filesystem::path& library) { return "cluster library " + library.string(); }

std::string describe(const std::filesystem::path& library, const std::string& name) {
  return describe(library) + ", cluster '" + name + "'";
}

[[noreturn]] void fail(const std::string& where, const std::string& what) {
  throw std::runtime_error(where + ": " + what);
}

// ---- attributes the shared helpers do not cover ---------------------------------------------

template <class T>
void write_scalar_attribute(hid_t object, const std::string& name, hid_t file_type, hid_t memory_type, T value) {
  const std::string file = hdf5_file_name(object);
  const Hdf5Handle space = checked_handle(H5Screate(H5S_SCALAR), H5Sclose, "create dataspace", file);
  const Hdf5Handle attribute =
      checked_handle(H5Acreate2(object, name.c_str(), file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
                     "create attribute " + name, file);
  check_status(H5Awrite(attribute.get(), memory_type, &value), "write attribute " + name, file);
}

std::uint64_t read_unsigned_attribute(hid_t object, const std::string& name) {
  const std::string file = hdf5_file_name(object);
  const Hdf5Handle attribute =
      checked_handle(H5Aopen(object, name.c_str(), H5P_DEFAULT), H5Aclose, "open attribute " + name, file);
  const Hdf5Handle space = checked_handle(H5Aget_space(attribute.get()), H5Sclose, "query attribute " + name, file);
  if (H5Sget_simple_extent_npoints(space.get()) != 1) throw_hdf5_error("attribute " + name + " is not a scalar", file);
  std::uint64_t value = 0;
  check_status(H5Aread(attribute.get(), H5T_NATIVE_UINT64, &value), "read attribute " + name, file);
  return value;
}

double read_scalar_float(hid_t object, const std::string& name) {
  const std::vector<double> values = read_float_attribute(object, name);
  if (values.size() != 1) throw_hdf5_error("attribute " + name + " is not a scalar", hdf5_file_name(object));
  return values[0];
}

std::string read_scalar_string(hid_t object, const std::string& name) {
  const std::vector<std::string> values = read_string_attribute(object, name);
  if (values.size() != 1) throw_hdf5_error("attribute " + name + " is not a scalar", hdf5_file_name(object));
  return values[0];
}

// ---- the file and its format ----------------------------------------------------------------

Hdf5Handle create_library_file(const std::filesystem::path& library) {
  const std::string path = library.string();
  const Hdf5Handle access = checked_handle(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "create file properties", path);
  check_status(H5Pset_libver_bounds(access.get(), H5F_LIBVER_V18, H5F_LIBVER_V18), "select file format", path);
  Hdf5Handle file =
      checked_handle(H5Fcreate(path.c_str(), H5F_ACC_EXCL, H5P_DEFAULT, access.get()), H5Fclose, "create file", path);

  const Hdf5Handle format = create_group(file.get(), "aerobreak");
  write_string_attribute(format.get(), "format", kFormatName);
  write_integer_array_attribute(format.get(), "format_version", {kFormatMajor, kFormatMinor});
  write_string_attribute(format.get(), "creator", "aerobreak " + std::string(version()));

  // Tracking creation order lets list_clusters report the clusters in the order they were stored.
  const Hdf5Handle group_properties =
      checked_handle(H5Pcreate(H5P_GROUP_CREATE), H5Pclose, "create group properties", path);
  check_status(H5Pset_link_creation_order(group_properties.get(), H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED),
               "track creation order", path);
  checked_handle(H5Gcreate2(file.get(), kClustersGroup, H5P_DEFAULT, group_properties.get(), H5P_DEFAULT), H5Gclose,
                 "create group clusters", path);
  return file;
}

void require_library_format(hid_t file, const std::string& where) {
  if (!link_exists(file, "aerobreak") || !link_exists(file, kClustersGroup))
    fail(where, "not an aerobreak cluster library (no /aerobreak or /clusters group)");
  const Hdf5Handle format = open_group(file, "aerobreak");
  if (!has_attribute(format.get(), "format") || read_scalar_string(format.get(), "format") != kFormatName)
    fail(where, "not an aerobreak cluster library (/aerobreak has no format \"" + std::string(kFormatName) + "\")");
  const std::vector<std::int64_t> format_version = has_attribute(format.get(), "format_version")
                                                       ? read_integer_attribute(format.get(), "format_version")
                                                       : std::vector<std::int64_t>{};
  if (format_version.size() != 2 || format_version[0] != kFormatMajor)
    fail(where,
         "unsupported cluster library format version (this aerobreak reads " + std::to_string(kFormatMajor) + ".x)");
}

// `where` names the library (and the cluster) in error messages.
Hdf5Handle open_library(const std::filesystem::path& library, unsigned mode, const std::string& where) {
  const std::string path = library.string();
  if (!std::filesystem::exists(library)) fail(where, "no such file");
  if (!is_hdf5_file(library)) fail(where, "not an aerobreak cluster library (not an HDF5 file)");
  Hdf5Handle file = checked_handle(H5Fopen(path.c_str(), mode, H5P_DEFAULT), H5Fclose, "open file", path);
  require_library_format(file.get(), where);
  return file;
}

Hdf5Handle open_or_create_library(const std::filesystem::path& library, const std::string& where) {
  if (std::filesystem::exists(library)) return open_library(library, H5F_ACC_RDWR, where);
  return create_library_file(library);
}

// ---- one cluster ----------------------------------------------------------------------------

void require_valid_name(const std::string& name, const std::string& where) {
  if (name.empty()) fail(where, "a cluster name must not be empty");
  if (name.find('/') != std::string::npos) fail(where, "a cluster name must not contain '/'");
  if (name == ".") fail(where, "a cluster name must not be \".\"");
}

void require_storable(const Cluster& cluster, const std::string& where) {
  if (cluster.size() == 0) fail(where, "cannot store a cluster without primaries");
  if (cluster.radius.size() != cluster.position.size())
    fail(where, "cluster has " + std::to_string(cluster.position.size()) + " positions but " +
                    std::to_string(cluster.radius.size()) + " radii");
  for (std::size_t i = 0; i < cluster.size(); ++i) {
    const Vec3& x = cluster.position[i];
    if (!std::isfinite(x.x) || !std::isfinite(x.y) || !std::isfinite(x.z))
      fail(where, "primary " + std::to_string(i) + " has a non-finite position");
    if (!(cluster.radius[i] > 0.0) || !std::isfinite(cluster.radius[i]))
      fail(where, "primary " + std::to_string(i) + " has a radius that is not positive and finite");
  }
}

void write_cluster_group(hid_t clusters, const std::string& name, const Cluster& cluster, const ClusterOrigin& origin) {
  const Hdf5Handle group = create_group(clusters, name);
  const hsize_t n = cluster.size();
  write_dataset(group.get(), "position", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {n, 3}, cluster.position.data());
  write_dataset(group.get(), "radius", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {n}, cluster.radius.data());

  write_string_attribute(group.get(), "generator", origin.generator);
  write_string_attribute(group.get(), "parameters", origin.parameters);
  write_scalar_attribute(group.get(), "seed", H5T_STD_U64LE, H5T_NATIVE_UINT64, origin.seed);
  write_scalar_attribute<std::uint8_t>(group.get(), "relaxed", H5T_STD_U8LE, H5T_NATIVE_UINT8, origin.relaxed ? 1 : 0);
  write_scalar_attribute(group.get(), "prefactor", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, origin.prefactor);
  write_scalar_attribute<std::uint64_t>(group.get(), "primary_count", H5T_STD_U64LE, H5T_NATIVE_UINT64, n);
  write_scalar_attribute(group.get(), "radius_of_gyration", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE,
                         radius_of_gyration(cluster));
  write_scalar_attribute(group.get(), "fractal_dimension", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE,
                         mass_radius_dimension(cluster));
  write_string_attribute(group.get(), "aerobreak_version", version());
  write_string_attribute(group.get(), "aerobreak_commit", git_commit());
}

std::vector<double> read_vector_dataset(hid_t group, const std::string& name, const std::vector<hsize_t>& shape,
                                        const std::string& where) {
  const Hdf5Handle dataset = open_dataset(group, name);
  if (dataset_shape(dataset.get()) != shape) fail(where, "dataset " + name + " has an unexpected shape");
  std::size_t count = 1;
  for (const hsize_t extent : shape) count *= extent;
  std::vector<double> values(count);
  read_dataset(dataset.get(), H5T_NATIVE_DOUBLE, values.data());
  return values;
}

Cluster read_cluster_arrays(hid_t group, const std::string& where) {
  if (!link_exists(group, "position") || !link_exists(group, "radius"))
    fail(where, "malformed cluster (no position or radius dataset)");
  const Hdf5Handle position = open_dataset(group, "position");
  const std::vector<hsize_t> shape = dataset_shape(position.get());
  if (shape.size() != 2 || shape[1] != 3 || shape[0] == 0) fail(where, "dataset position is not of shape [N, 3]");
  const hsize_t n = shape[0];

  Cluster cluster;
  cluster.position.resize(n);
  read_dataset(position.get(), H5T_NATIVE_DOUBLE, cluster.position.data());
  cluster.radius = read_vector_dataset(group, "radius", {n}, where);
  return cluster;
}

ClusterMetadata read_cluster_metadata(hid_t group) {
  ClusterMetadata metadata;
  metadata.origin.generator = read_scalar_string(group, "generator");
  metadata.origin.parameters = read_scalar_string(group, "parameters");
  metadata.origin.seed = read_unsigned_attribute(group, "seed");
  metadata.origin.relaxed = read_unsigned_attribute(group, "relaxed") != 0;
  metadata.origin.prefactor = read_scalar_float(group, "prefactor");
  metadata.primary_count = static_cast<std::size_t>(read_unsigned_attribute(group, "primary_count"));
  metadata.radius_of_gyration = read_scalar_float(group, "radius_of_gyration");
  metadata.fractal_dimension = read_scalar_float(group, "fractal_dimension");
  metadata.aerobreak_version = read_scalar_string(group, "aerobreak_version");
  metadata.aerobreak_commit = read_scalar_string(group, "aerobreak_commit");
  return metadata;
}

std::vector<std::string> cluster_names(hid_t file, const std::filesystem::path& library) {
  const std::string path = library.string();
  const Hdf5Handle clusters = open_group(file, kClustersGroup);
  H5G_info_t info;
  check_status(H5Gget_info(clusters.get(), &info), "query group clusters", path);
  std::vector<std::string> names;
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    const ssize_t length =
        H5Lget_name_by_idx(clusters.get(), ".", H5_INDEX_CRT_ORDER, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
    if (length < 0) throw_hdf5_error("list clusters", path);
    std::string name(static_cast<std::size_t>(length) + 1, '\0');
    H5Lget_name_by_idx(clusters.get(), ".", H5_INDEX_CRT_ORDER, H5_ITER_INC, i, name.data(), name.size(), H5P_DEFAULT);
    name.resize(static_cast<std::size_t>(length));
    names.push_back(std::move(name));
  }
  return names;
}

std::string missing_cluster_message(const std::vector<std::string>& names) {
  if (names.empty()) return "no such cluster (the library is empty)";
  std::string message = "no such cluster (the library holds ";
  for (std::size_t i = 0; i < names.size() && i < kNamesShownWhenMissing; ++i)
    message += (i == 0 ? "'" : ", '") + names[i] + "'";
  if (names.size() > kNamesShownWhenMissing)
    message += " and " + std::to_string(names.size() - kNamesShownWhenMissing) + " more";
  return message + ")";
}

// Runs `action`, rewording any error other than the library's own as one about `where`.
template <class Action>
auto with_context(const std::string& where, Action action) {
  const Hdf5ErrorSilencer silence;
  try {
    return action();
  } catch (const std::runtime_error& error) {
    const std::string message = error.what();
    if (message.rfind(where, 0) == 0) throw;
    throw std::runtime_error(where + ": " + message);
  }
}

}  // namespace

void store_cluster(const std::filesystem::path& library, const std::string& name, const Cluster& cluster,
                   const ClusterOrigin& origin, ExistingCluster existing) {
  const std::string where = describe(library, name);
  with_context(where, [&] {
    require_valid_name(name, where);
    require_storable(cluster, where);
    const Hdf5Handle file = open_or_create_library(library, where);
    const Hdf5Handle clusters = open_group(file.get(), kClustersGroup);
    if (link_exists(clusters.get(), name)) {
      if (existing == ExistingCluster::reject) fail(where, "a cluster of that name is already stored");
      check_status(H5Ldelete(clusters.get(), name.c_str(), H5P_DEFAULT), "delete old cluster " + name,
                   library.string());
    }
    try {
      write_cluster_group(clusters.get(), name, cluster, origin);
    } catch (...) {
      H5Ldelete(clusters.get(), name.c_str(), H5P_DEFAULT);
      throw;
    }
  });
}

std::vector<std::string> list_clusters(const std::filesystem::path& library) {
  const std::string where = describe(library);
  return with_context(where, [&] {
    const Hdf5Handle file = open_library(library, H5F_ACC_RDONLY, where);
    return cluster_names(file.get(), library);
  });
}

StoredCluster read_cluster(const std::filesystem::path& library, const std::string& name) {
  const std::string where = describe(library, name);
  return with_context(where, [&] {
    require_valid_name(name, where);
    const Hdf5Handle file = open_library(library, H5F_ACC_RDONLY, where);
    const Hdf5Handle clusters = open_group(file.get(), kClustersGroup);
    if (!link_exists(clusters.get(), name)) fail(where, missing_cluster_message(cluster_names(file.get(), library)));
    const Hdf5Handle group = open_group(clusters.get(), name);
    StoredCluster stored;
    stored.name = name;
    stored.cluster = read_cluster_arrays(group.get(), where);
    stored.metadata = read_cluster_metadata(group.get());
    return stored;
  });
}

bool is_hdf5_file(const std::filesystem::path& path) {
  const Hdf5ErrorSilencer silence;
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) return false;
#if H5_VERSION_GE(1, 12, 0)
  const htri_t result = H5Fis_accessible(path.string().c_str(), H5P_DEFAULT);
#else
  const htri_t result = H5Fis_hdf5(path.string().c_str());
#endif
  H5Eclear2(H5E_DEFAULT);
  return result > 0;
}

}  // namespace aerobreak
