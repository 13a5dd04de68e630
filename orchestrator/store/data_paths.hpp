#pragma once
#include <filesystem>
#include <string>

namespace aerobreak {

// Where a store keeps the paths of its cases' data files (docs/ORCHESTRATOR.md, "Store"): relative
// to its data folder, so that a store moved or copied together with its data folder finds every
// file where it now lies.

// The data folder a store has unless told otherwise: the store file with its extension replaced
// by .data (runs/default.sqlite -> runs/default.data).
std::filesystem::path default_data_directory(const std::filesystem::path& store_file);

// How the store records `file`: relative to `data_directory` when it lies under it (every file
// the scheduler asks workers for does: cases/HASH.h5), as given otherwise.
std::string stored_data_path(const std::filesystem::path& data_directory, const std::string& file);

// Where a recorded path lies now: under `data_directory` when it is relative, as recorded when it
// is absolute.
std::string data_path_on_disk(const std::filesystem::path& data_directory, const std::string& stored);

}  // namespace aerobreak
