#include "engine/io/hdf5_attributes.hpp"

#include <algorithm>
#include <cstring>

#include "engine/io/hdf5_handle.hpp"

namespace aerobreak {

namespace {

// A fixed-length, null-terminated string type holding up to `characters` characters.
Hdf5Handle fixed_string_type(std::size_t characters, const std::string& file) {
  Hdf5Handle type = checked_handle(H5Tcopy(H5T_C_S1), H5Tclose, "copy string type", file);
  check_status(H5Tset_size(type.get(), characters + 1), "size string type", file);
  check_status(H5Tset_strpad(type.get(), H5T_STR_NULLTERM), "pad string type", file);
  return type;
}

Hdf5Handle simple_space(hsize_t length, const std::string& file) {
  return checked_handle(H5Screate_simple(1, &length, nullptr), H5Sclose, "create dataspace", file);
}

Hdf5Handle scalar_space(const std::string& file) {
  return checked_handle(H5Screate(H5S_SCALAR), H5Sclose, "create dataspace", file);
}

void write_attribute(hid_t object, const std::string& name, hid_t file_type, hid_t memory_type, hid_t space,
                     const void* data) {
  const std::string file = hdf5_file_name(object);
  const Hdf5Handle attribute =
      checked_handle(H5Acreate2(object, name.c_str(), file_type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
                     "create attribute " + name, file);
  check_status(H5Awrite(attribute.get(), memory_type, data), "write attribute " + name, file);
}

struct OpenAttribute {
  Hdf5Handle attribute;
  std::size_t value_count = 0;
};

OpenAttribute open_attribute(hid_t object, const std::string& name, const std::string& file) {
  OpenAttribute result;
  result.attribute =
      checked_handle(H5Aopen(object, name.c_str(), H5P_DEFAULT), H5Aclose, "open attribute " + name, file);
  const Hdf5Handle space =
      checked_handle(H5Aget_space(result.attribute.get()), H5Sclose, "query attribute " + name, file);
  const hssize_t count = H5Sget_simple_extent_npoints(space.get());
  if (count < 0) throw_hdf5_error("query attribute " + name, file);
  result.value_count = static_cast<std::size_t>(count);
  return result;
}

template <class T>
std::vector<T> read_numeric_attribute(hid_t object, const std::string& name, hid_t memory_type) {
  const std::string file = hdf5_file_name(object);
  const OpenAttribute opened = open_attribute(object, name, file);
  std::vector<T> values(opened.value_count);
  check_status(H5Aread(opened.attribute.get(), memory_type, values.data()), "read attribute " + name, file);
  return values;
}

}  // namespace

void write_string_attribute(hid_t object, const std::string& name, std::string_view value) {
  const std::string file = hdf5_file_name(object);
  const Hdf5Handle type = fixed_string_type(value.size(), file);
  const std::string terminated(value);
  write_attribute(object, name, type.get(), type.get(), scalar_space(file).get(), terminated.c_str());
}

void write_string_array_attribute(hid_t object, const std::string& name, const std::vector<std::string>& values) {
  const std::string file = hdf5_file_name(object);
  std::size_t longest = 0;
  for (const auto& value : values) longest = std::max(longest, value.size());
  const std::size_t stride = longest + 1;
  std::vector<char> packed(values.size() * stride, '\0');
  for (std::size_t i = 0; i < values.size(); ++i) std::memcpy(&packed[i * stride], values[i].data(), values[i].size());
  const Hdf5Handle type = fixed_string_type(longest, file);
  write_attribute(object, name, type.get(), type.get(), simple_space(values.size(), file).get(), packed.data());
}

void write_integer_attribute(hid_t object, const std::string& name, std::int32_t value) {
  const std::string file = hdf5_file_name(object);
  write_attribute(object, name, H5T_STD_I32LE, H5T_NATIVE_INT32, scalar_space(file).get(), &value);
}

void write_integer_array_attribute(hid_t object, const std::string& name, const std::vector<std::int32_t>& values) {
  const std::string file = hdf5_file_name(object);
  write_attribute(object, name, H5T_STD_I32LE, H5T_NATIVE_INT32, simple_space(values.size(), file).get(),
                  values.data());
}

bool has_attribute(hid_t object, const std::string& name) {
  const htri_t exists = H5Aexists(object, name.c_str());
  if (exists < 0) throw_hdf5_error("look up attribute " + name, hdf5_file_name(object));
  return exists > 0;
}

std::vector<std::int64_t> read_integer_attribute(hid_t object, const std::string& name) {
  return read_numeric_attribute<std::int64_t>(object, name, H5T_NATIVE_INT64);
}

std::vector<double> read_float_attribute(hid_t object, const std::string& name) {
  return read_numeric_attribute<double>(object, name, H5T_NATIVE_DOUBLE);
}

std::vector<std::string> read_string_attribute(hid_t object, const std::string& name) {
  const std::string file = hdf5_file_name(object);
  const OpenAttribute opened = open_attribute(object, name, file);
  const Hdf5Handle stored_type =
      checked_handle(H5Aget_type(opened.attribute.get()), H5Tclose, "query attribute " + name, file);
  if (H5Tget_class(stored_type.get()) != H5T_STRING || H5Tis_variable_str(stored_type.get()) != 0)
    throw_hdf5_error("attribute " + name + " is not a fixed-length string", file);
  const std::size_t stored_size = H5Tget_size(stored_type.get());
  const Hdf5Handle memory_type = fixed_string_type(stored_size, file);
  const std::size_t stride = stored_size + 1;
  std::vector<char> packed(opened.value_count * stride, '\0');
  check_status(H5Aread(opened.attribute.get(), memory_type.get(), packed.data()), "read attribute " + name, file);
  std::vector<std::string> values;
  for (std::size_t i = 0; i < opened.value_count; ++i) values.emplace_back(&packed[i * stride]);
  return values;
}

}  // namespace aerobreak
