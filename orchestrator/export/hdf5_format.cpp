// The HDF5 format of docs/EXPORT.md, written to memory (the core driver without a backing file).
#include <hdf5.h>

#include <mutex>

#include "engine/io/hdf5_attributes.hpp"
#include "engine/io/hdf5_datasets.hpp"
#include "engine/io/hdf5_handle.hpp"
#include "orchestrator/export/table_formats.hpp"

namespace aerobreak {
namespace {

// Debian's HDF5 is built without thread safety: one table at a time, whatever the server thread.
std::mutex hdf5_mutex;

const char* role_text(ColumnRole role) {
  return role == ColumnRole::speed     ? "speed"
         : role == ColumnRole::input   ? "input"
         : role == ColumnRole::derived ? "derived"
                                       : "output";
}

void write_columns(hid_t file, const LookupTable& table) {
  for (const auto& column : table.columns) {
    write_dataset(file, column.name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {static_cast<hsize_t>(column.values.size())},
                  column.values.data());
    auto dataset = open_dataset(file, column.name);
    write_string_attribute(dataset.get(), "units", column.unit);
    write_string_attribute(dataset.get(), "description", column.description);
    write_string_attribute(dataset.get(), "role", role_text(column.role));
  }
}

}  // namespace

std::string hdf5_image(const LookupTable& table) {
  std::lock_guard lock(hdf5_mutex);
  Hdf5ErrorSilencer silencer;
  const std::string name = "lookup.h5";
  auto access = checked_handle(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "file access list", name);
  check_status(H5Pset_fapl_core(access.get(), 1 << 16, 0), "core driver", name);
  auto file =
      checked_handle(H5Fcreate(name.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get()), H5Fclose, "create", name);
  for (const auto& [key, value] : metadata_lines(table.metadata)) write_string_attribute(file.get(), key, value);
  write_columns(file.get(), table);
  check_status(H5Fflush(file.get(), H5F_SCOPE_GLOBAL), "flush", name);
  const ssize_t size = H5Fget_file_image(file.get(), nullptr, 0);
  if (size <= 0) throw_hdf5_error("file image size", name);
  std::string image(static_cast<std::size_t>(size), '\0');
  if (H5Fget_file_image(file.get(), image.data(), image.size()) != size) throw_hdf5_error("file image", name);
  return image;
}

}  // namespace aerobreak
