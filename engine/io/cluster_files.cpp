#include "engine/io/cluster_files.hpp"

#include <algorithm>
#include <cctype>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "engine/io/xyz.hpp"

namespace aerobreak {
namespace {

void require_existing_file(const std::filesystem::path& path) {
  if (!std::filesystem::exists(path)) throw std::runtime_error("no such file: " + path.string());
}

NamedCluster read_library_entry(const std::filesystem::path& library, const std::string& name) {
  StoredCluster stored = read_cluster(library, name);
  return {stored.name, std::move(stored.cluster), std::move(stored.metadata)};
}

// The clusters of a library: the one named, or all of them for an empty name.
std::vector<NamedCluster> read_library(const std::filesystem::path& library, const std::string& name) {
  std::vector<NamedCluster> clusters;
  const std::vector<std::string> names = name.empty() ? list_clusters(library) : std::vector<std::string>{name};
  for (const std::string& each : names) clusters.push_back(read_library_entry(library, each));
  return clusters;
}

// A text file's cluster, named after the file.
NamedCluster read_text_cluster(const std::filesystem::path& path) {
  NamedCluster named{path.stem().string(), read_xyz_cluster(path), {}};
  if (named.cluster.size() == 0) throw std::runtime_error(path.string() + ": no particles in the file");
  return named;
}

// "a, b, c", with at most `shown` names and a count of the rest.
std::string joined(const std::vector<std::string>& names, std::size_t shown = 10) {
  std::string text;
  for (std::size_t i = 0; i < names.size() && i < shown; ++i) text += (i == 0 ? "" : ", ") + names[i];
  if (names.size() > shown) text += " and " + std::to_string(names.size() - shown) + " more";
  return text;
}

ClusterOrigin imported_origin(const std::filesystem::path& source) {
  ClusterOrigin origin;
  origin.generator = "xyz";
  origin.parameters = nlohmann::ordered_json{{"source", source.string()}}.dump();
  return origin;
}

std::vector<NamedCluster> read_for_conversion(const std::filesystem::path& input, const std::string& name,
                                              bool to_library) {
  require_existing_file(input);
  if (!is_hdf5_file(input)) {
    NamedCluster text = read_text_cluster(input);
    if (!name.empty()) text.name = name;
    return {std::move(text)};
  }
  if (name.empty() && !to_library)
    throw std::runtime_error("converting a library to XYZ needs --name (" + input.string() +
                             " holds: " + joined(list_clusters(input)) + ")");
  return read_library(input, name);
}

}  // namespace

bool names_cluster_library(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == ".h5" || extension == ".hdf5";
}

std::vector<NamedCluster> read_cluster_file(const std::filesystem::path& path, const std::string& name) {
  require_existing_file(path);
  if (is_hdf5_file(path)) return read_library(path, name);
  if (!name.empty())
    throw std::runtime_error("--name selects a cluster of a library, and " + path.string() + " is not an HDF5 file");
  return {read_text_cluster(path)};
}

std::size_t convert_cluster_file(const std::filesystem::path& input, const std::filesystem::path& output,
                                 const std::string& name, ExistingCluster existing) {
  const bool to_library = names_cluster_library(output);
  const std::vector<NamedCluster> clusters = read_for_conversion(input, name, to_library);
  for (const NamedCluster& each : clusters) {
    if (!to_library) {
      write_xyz_cluster(output, each.cluster);
      continue;
    }
    const ClusterOrigin origin = each.metadata ? each.metadata->origin : imported_origin(input);
    store_cluster(output, each.name, each.cluster, origin, existing);
  }
  return clusters.size();
}

}  // namespace aerobreak
