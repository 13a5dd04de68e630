#include "engine/io/hdf5_datasets.hpp"

#include <algorithm>
#include <functional>
#include <numeric>

namespace aerobreak {

namespace {

// Rows per chunk: aim at chunks of about 64 KiB (well inside HDF5's default 1 MiB chunk cache,
// so appending one row at a time does not rewrite chunks), at least one row, at most 1024 rows.
hsize_t rows_per_chunk(std::size_t bytes_per_row) {
  constexpr std::size_t target_chunk_bytes = 64 * 1024;
  constexpr std::size_t max_rows = 1024;
  const std::size_t rows = target_chunk_bytes / std::max<std::size_t>(bytes_per_row, 1);
  return static_cast<hsize_t>(std::clamp<std::size_t>(rows, 1, max_rows));
}

hsize_t product(const std::vector<hsize_t>& dims) {
  return std::accumulate(dims.begin(), dims.end(), hsize_t{1}, std::multiplies<>());
}

Hdf5Handle space_of(hid_t dataset, const std::string& file) {
  return checked_handle(H5Dget_space(dataset), H5Sclose, "query dataspace", file);
}

Hdf5Handle simple_space(const std::vector<hsize_t>& dims, const std::string& file) {
  if (dims.empty()) return checked_handle(H5Screate(H5S_SCALAR), H5Sclose, "create dataspace", file);
  return checked_handle(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose,
                        "create dataspace", file);
}

// Selects row `index` (the whole extent of every other dimension) in `space` of shape `dims`;
// returns the shape of that row for a matching memory dataspace.
std::vector<hsize_t> select_row(hid_t space, const std::vector<hsize_t>& dims, hsize_t index, const std::string& file) {
  std::vector<hsize_t> start(dims.size(), 0);
  std::vector<hsize_t> count = dims;
  start[0] = index;
  count[0] = 1;
  check_status(H5Sselect_hyperslab(space, H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr), "select row",
               file);
  std::vector<hsize_t> row(dims.begin() + 1, dims.end());
  if (row.empty()) row.push_back(1);
  return row;
}

}  // namespace

Hdf5Handle create_group(hid_t parent, const std::string& name) {
  return checked_handle(H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                        "create group " + name, hdf5_file_name(parent));
}

Hdf5Handle open_group(hid_t parent, const std::string& name) {
  return checked_handle(H5Gopen2(parent, name.c_str(), H5P_DEFAULT), H5Gclose, "open group " + name,
                        hdf5_file_name(parent));
}

Hdf5Handle open_dataset(hid_t parent, const std::string& name) {
  return checked_handle(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), H5Dclose, "open dataset " + name,
                        hdf5_file_name(parent));
}

bool link_exists(hid_t parent, const std::string& name) {
  std::size_t end = 0;
  while (end != std::string::npos) {
    end = name.find('/', end + 1);
    const std::string prefix = name.substr(0, end);
    const htri_t exists = H5Lexists(parent, prefix.c_str(), H5P_DEFAULT);
    if (exists < 0) throw_hdf5_error("look up " + prefix, hdf5_file_name(parent));
    if (exists == 0) return false;
  }
  return true;
}

void create_hard_link(hid_t target, hid_t parent, const std::string& name) {
  check_status(H5Lcreate_hard(target, ".", parent, name.c_str(), H5P_DEFAULT, H5P_DEFAULT), "link " + name,
               hdf5_file_name(parent));
}

Hdf5Handle create_extendable_dataset(hid_t parent, const std::string& name, hid_t file_type,
                                     const std::vector<hsize_t>& row_shape) {
  const std::string file = hdf5_file_name(parent);
  std::vector<hsize_t> dims{0};
  dims.insert(dims.end(), row_shape.begin(), row_shape.end());
  std::vector<hsize_t> max_dims = dims;
  max_dims[0] = H5S_UNLIMITED;
  std::vector<hsize_t> chunk = dims;
  chunk[0] = rows_per_chunk(H5Tget_size(file_type) * product(row_shape));

  const Hdf5Handle space = checked_handle(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), max_dims.data()),
                                          H5Sclose, "create dataspace for " + name, file);
  const Hdf5Handle properties =
      checked_handle(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, "create properties for " + name, file);
  check_status(H5Pset_chunk(properties.get(), static_cast<int>(chunk.size()), chunk.data()), "chunk " + name, file);
  return checked_handle(
      H5Dcreate2(parent, name.c_str(), file_type, space.get(), H5P_DEFAULT, properties.get(), H5P_DEFAULT), H5Dclose,
      "create dataset " + name, file);
}

void append_row(hid_t dataset, hid_t memory_type, const void* row) {
  const std::string file = hdf5_file_name(dataset);
  std::vector<hsize_t> dims = dataset_shape(dataset);
  const hsize_t index = dims.at(0);
  dims[0] = index + 1;
  check_status(H5Dset_extent(dataset, dims.data()), "extend dataset", file);
  const Hdf5Handle file_space = space_of(dataset, file);
  const Hdf5Handle memory_space = simple_space(select_row(file_space.get(), dims, index, file), file);
  check_status(H5Dwrite(dataset, memory_type, memory_space.get(), file_space.get(), H5P_DEFAULT, row), "append row",
               file);
}

void read_row(hid_t dataset, hsize_t index, hid_t memory_type, void* row) {
  const std::string file = hdf5_file_name(dataset);
  const std::vector<hsize_t> dims = dataset_shape(dataset);
  if (dims.empty() || index >= dims[0]) throw_hdf5_error("row " + std::to_string(index) + " out of range", file);
  const Hdf5Handle file_space = space_of(dataset, file);
  const Hdf5Handle memory_space = simple_space(select_row(file_space.get(), dims, index, file), file);
  check_status(H5Dread(dataset, memory_type, memory_space.get(), file_space.get(), H5P_DEFAULT, row), "read row", file);
}

void write_dataset(hid_t parent, const std::string& name, hid_t file_type, hid_t memory_type,
                   const std::vector<hsize_t>& shape, const void* data) {
  const std::string file = hdf5_file_name(parent);
  const Hdf5Handle space = simple_space(shape, file);
  const Hdf5Handle dataset =
      checked_handle(H5Dcreate2(parent, name.c_str(), file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                     H5Dclose, "create dataset " + name, file);
  check_status(H5Dwrite(dataset.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "write dataset " + name,
               file);
}

void read_dataset(hid_t dataset, hid_t memory_type, void* data) {
  check_status(H5Dread(dataset, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "read dataset",
               hdf5_file_name(dataset));
}

std::vector<hsize_t> dataset_shape(hid_t dataset) {
  const std::string file = hdf5_file_name(dataset);
  const Hdf5Handle space = space_of(dataset, file);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank < 0) throw_hdf5_error("query dataset rank", file);
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  if (rank > 0) check_status(H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr), "query dataset shape", file);
  return dims;
}

}  // namespace aerobreak
