#include "orchestrator/worker/line_reader.hpp"

#include <poll.h>
#include <unistd.h>

#include <array>
#include <cerrno>

namespace aerobreak {

std::vector<std::string> LineReader::read(std::chrono::milliseconds timeout) {
  std::vector<std::string> lines;
  if (ended_) return lines;
  pollfd waiting{fd_, POLLIN, 0};
  const int ready = ::poll(&waiting, 1, static_cast<int>(timeout.count()));
  if (ready <= 0) return lines;  // timeout, or a signal: the caller comes back soon

  std::array<char, 65536> buffer;
  const ssize_t got = ::read(fd_, buffer.data(), buffer.size());
  if (got < 0 && (errno == EINTR || errno == EAGAIN)) return lines;
  if (got <= 0) {
    ended_ = true;
    if (!pending_.empty() && pending_.back() == '\r') pending_.pop_back();
    if (!pending_.empty()) lines.push_back(std::move(pending_));
    return lines;
  }
  pending_.append(buffer.data(), static_cast<std::size_t>(got));
  std::size_t begin = 0;
  for (std::size_t end; (end = pending_.find('\n', begin)) != std::string::npos; begin = end + 1) {
    std::size_t length = end - begin;
    if (length > 0 && pending_[end - 1] == '\r') --length;
    lines.push_back(pending_.substr(begin, length));
  }
  pending_.erase(0, begin);
  return lines;
}

}  // namespace aerobreak
