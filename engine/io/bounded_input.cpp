#include "engine/io/bounded_input.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>

namespace aerobreak {
namespace {

[[noreturn]] void refuse(const std::filesystem::path& path, std::string_view what, const std::string& problem) {
  throw InputFileError(std::string(what) + " " + path.string() + ": " + problem);
}

std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

void check_status(const std::filesystem::path& path, const struct stat& status, std::uintmax_t max_bytes,
                  std::string_view what) {
  if (!S_ISREG(status.st_mode)) refuse(path, what, "is " + kind_of(status.st_mode) + ", not a regular file");
  if (static_cast<std::uintmax_t>(status.st_size) > max_bytes)
    refuse(
        path, what,
        "has " + std::to_string(status.st_size) + " bytes, more than the " + std::to_string(max_bytes) + " read here");
}

[[noreturn]] void cannot_open(const std::filesystem::path& path, std::string_view what) {
  throw InputFileError("cannot open " + std::string(what) + " " + path.string() + ": " + std::strerror(errno));
}

// Closes the descriptor when it goes out of scope.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

void require_regular_file(const std::filesystem::path& path, std::uintmax_t max_bytes, std::string_view what) {
  struct stat status {};
  if (::stat(path.c_str(), &status) != 0) cannot_open(path, what);
  check_status(path, status, max_bytes, what);
}

std::string read_regular_file(const std::filesystem::path& path, std::uintmax_t max_bytes, std::string_view what) {
  // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer.
  const Descriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC)};
  if (file.fd < 0) cannot_open(path, what);
  struct stat status {};
  if (::fstat(file.fd, &status) != 0) refuse(path, what, std::strerror(errno));
  check_status(path, status, max_bytes, what);

  std::string text(static_cast<std::size_t>(status.st_size), '\0');
  std::size_t filled = 0;
  for (;;) {
    if (filled == text.size()) {
      // A file that grew since fstat: read on, within the limit.
      if (text.size() >= max_bytes) {
        char probe;
        if (::read(file.fd, &probe, 1) > 0) refuse(path, what, "grew past " + std::to_string(max_bytes) + " bytes");
        break;
      }
      text.resize(std::min<std::uintmax_t>(max_bytes, text.size() + 65536));
    }
    const ssize_t n = ::read(file.fd, text.data() + filled, text.size() - filled);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) refuse(path, what, std::strerror(errno));
    if (n == 0) break;
    filled += static_cast<std::size_t>(n);
  }
  text.resize(filled);
  return text;
}

std::string read_first_line(const std::filesystem::path& path, std::string_view what, std::uintmax_t max_bytes) {
  std::string line = read_regular_file(path, max_bytes, what);
  line.erase(std::min(line.find('\n'), line.size()));
  while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back()))) line.pop_back();
  return line;
}

}  // namespace aerobreak
