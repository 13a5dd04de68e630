#pragma once
#include <hdf5.h>

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace aerobreak {

// Attribute writers and readers with the data types H5MD mandates. Strings are fixed-length,
// null-terminated (H5MD 1.1, "H5MD metadata" and "Simulation box": "fixed-length string
// datatype"). Every function throws std::runtime_error naming the file on failure.

void write_string_attribute(hid_t object, const std::string& name, std::string_view value);
void write_string_array_attribute(hid_t object, const std::string& name, const std::vector<std::string>& values);
void write_integer_attribute(hid_t object, const std::string& name, std::int32_t value);
void write_integer_array_attribute(hid_t object, const std::string& name, const std::vector<std::int32_t>& values);

bool has_attribute(hid_t object, const std::string& name);

// All values of a numeric attribute (scalar or array), converted by HDF5 to the requested type.
std::vector<std::int64_t> read_integer_attribute(hid_t object, const std::string& name);
std::vector<double> read_float_attribute(hid_t object, const std::string& name);

// All values of a fixed-length string attribute (scalar or array).
std::vector<std::string> read_string_attribute(hid_t object, const std::string& name);

}  // namespace aerobreak
