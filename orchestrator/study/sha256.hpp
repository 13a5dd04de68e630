#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace aerobreak {

// SHA-256 (FIPS 180-4, section 6.2) of a byte string: the 32-byte digest, and the same as 64
// lower-case hex digits. Used to name cases and studies by their content and to derive seeds, so
// it must give the standard digest on every platform (tests check the NIST example vectors).
std::array<std::uint8_t, 32> sha256(std::string_view message);
std::string sha256_hex(std::string_view message);

}  // namespace aerobreak
