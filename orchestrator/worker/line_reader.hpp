#pragma once
#include <chrono>
#include <string>
#include <vector>

namespace aerobreak {

// Lines from a file descriptor (rank 0's stdin) without blocking longer than asked: poll() with a
// timeout, then whatever read() returns, cut at '\n' ('\r' before it dropped). A last line
// without '\n' is returned when the input ends.
class LineReader {
 public:
  explicit LineReader(int fd) : fd_(fd) {}

  // Complete lines that arrived within `timeout` (none if nothing did).
  std::vector<std::string> read(std::chrono::milliseconds timeout);

  // Whether the input has ended (EOF, or a read error, which means the same to the job).
  bool ended() const { return ended_; }

 private:
  int fd_;
  std::string pending_;
  bool ended_ = false;
};

}  // namespace aerobreak
