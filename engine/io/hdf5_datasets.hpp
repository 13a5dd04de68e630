#pragma once
#include <hdf5.h>

#include <string>
#include <vector>

#include "engine/io/hdf5_handle.hpp"

namespace aerobreak {

// Groups and datasets, in particular datasets that grow by one row per sample along an unlimited
// first dimension: the `[variable]` dimension of H5MD time-dependent data (H5MD 1.1,
// "Time-dependent data"). Every function throws std::runtime_error naming the file on failure.

Hdf5Handle create_group(hid_t parent, const std::string& name);
Hdf5Handle open_group(hid_t parent, const std::string& name);
Hdf5Handle open_dataset(hid_t parent, const std::string& name);

// Whether `name` (a path relative to `parent`) exists; every intermediate group must exist too.
bool link_exists(hid_t parent, const std::string& name);

// A hard link `parent/name` to an existing object, as H5MD allows for shared `step` and `time`.
void create_hard_link(hid_t target, hid_t parent, const std::string& name);

// An empty, chunked dataset of shape [0, row_shape...] with unlimited first dimension.
Hdf5Handle create_extendable_dataset(hid_t parent, const std::string& name, hid_t file_type,
                                     const std::vector<hsize_t>& row_shape);

// Grows the first dimension by one and writes one row (all remaining dimensions) from `row`.
void append_row(hid_t dataset, hid_t memory_type, const void* row);

// Reads row `index` of the first dimension into `row`.
void read_row(hid_t dataset, hsize_t index, hid_t memory_type, void* row);

// A fixed-size (time-independent) dataset written in full.
void write_dataset(hid_t parent, const std::string& name, hid_t file_type, hid_t memory_type,
                   const std::vector<hsize_t>& shape, const void* data);

// Reads a whole dataset into `data`, which must hold all its elements.
void read_dataset(hid_t dataset, hid_t memory_type, void* data);

// The current dimensions of a dataset; empty for a scalar dataset.
std::vector<hsize_t> dataset_shape(hid_t dataset);

}  // namespace aerobreak
