#pragma once
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace aerobreak {

// Reading a file a user names, bounded as the service bounds a request body (docs/ORCHESTRATOR.md,
// "Limits"): only a regular file (a FIFO, a device such as /dev/zero, a directory or a socket
// would block or never end), never more bytes than a limit checked before anything is read.

// The most bytes of a JSON document the program reads: a case or a study, as a request body.
constexpr std::uintmax_t kMaxDocumentBytes = std::uintmax_t{1} << 20;
// The most bytes of a text cluster file (XYZ): about 2.5 million primaries at 100 bytes a line.
constexpr std::uintmax_t kMaxClusterTextBytes = std::uintmax_t{256} << 20;

// A file that cannot be read as asked; what() names the file and the problem.
class InputFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws InputFileError unless `path` names an existing regular file of at most `max_bytes`
// (following links). `what` says what the file is meant to be ("case file", "cluster library").
void require_regular_file(const std::filesystem::path& path, std::uintmax_t max_bytes, std::string_view what);

// The whole of a regular file of at most `max_bytes`. Opened without blocking and checked on the
// open descriptor (so that a FIFO or device is refused, not waited for, and a file swapped after a
// check is not read), then read to its end, never past max_bytes. Throws InputFileError.
std::string read_regular_file(const std::filesystem::path& path, std::uintmax_t max_bytes, std::string_view what);

// The first line of a small regular file (a token file), without its line end and trailing blanks.
std::string read_first_line(const std::filesystem::path& path, std::string_view what, std::uintmax_t max_bytes = 4096);

}  // namespace aerobreak
