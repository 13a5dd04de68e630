#pragma once
#include <httplib.h>

#include <cstdint>
#include <filesystem>

#include "orchestrator/store/data_file_check.hpp"
#include "orchestrator/store/store.hpp"

namespace aerobreak {

// Answers with case `case_id`'s HDF5 (H5MD) file, streamed in chunks as an attachment. Only the file
// that the store names for that case is served, and only when it lies under `data_directory` (the
// service's STORE.data): no path comes from the client. RequestError 404 otherwise, 409 when the
// file's size or SHA-256 is not what its worker recorded (damaged).
void send_case_file(httplib::Response& response, Store& store, std::int64_t case_id,
                    const std::filesystem::path& data_directory, DataFileChecker& checker);

}  // namespace aerobreak
