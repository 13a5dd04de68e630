#pragma once
#include <filesystem>
#include <string>

namespace aerobreak {

// The SHA-256 (FIPS 180-4) of a file's contents as 64 lower-case hex digits, through OpenSSL's
// libcrypto (EVP), read in 64 KiB blocks; throws std::runtime_error naming the file when it cannot
// be opened or read. Checksums the bulk HDF5 file of each case, so that a damaged or replaced file
// is noticed.
std::string file_sha256_hex(const std::filesystem::path& file);

}  // namespace aerobreak
