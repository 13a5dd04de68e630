#pragma once
#include <string>

namespace aerobreak {

// RFC 1952 gzip of `text` (zlib's deflate with a gzip wrapper), at zlib's default level: what the
// service sends to a client that accepts gzip, compressed once per kept document or file.
std::string gzip(const std::string& text);

}  // namespace aerobreak
