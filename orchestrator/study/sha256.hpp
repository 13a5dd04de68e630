#pragma once
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace aerobreak {

// SHA-256 (FIPS 180-4) through OpenSSL's libcrypto (EVP interface). Used to name cases and studies
// by their content, to derive replicate seeds and to checksum files, so it must give the standard
// digest on every platform (tests check the FIPS 180-2 example vectors and hashes stored by
// earlier versions of aerobreak). Every function throws std::runtime_error when libcrypto fails.

using Sha256Digest = std::array<std::uint8_t, 32>;

// The digest of a byte string, and the same as 64 lower-case hex digits.
Sha256Digest sha256(std::string_view bytes);
std::string sha256_hex(std::string_view bytes);

// The digest of a file's contents, read in blocks (a file of any size in constant memory); throws
// std::runtime_error naming the file when it cannot be opened or read.
Sha256Digest sha256_of_file(const std::filesystem::path& file);
std::string sha256_hex_of_file(const std::filesystem::path& file);

// 64 lower-case hex digits of a digest.
std::string to_hex(const Sha256Digest& digest);

}  // namespace aerobreak
