#include "orchestrator/service/lingering_closes.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>

namespace aerobreak {
namespace {

constexpr std::size_t kLingerBytes = 4 << 20;

void close_now(socket_t socket) {
  ::shutdown(socket, SHUT_RDWR);
  ::close(socket);
}

}  // namespace

LingeringCloses::LingeringCloses() {
  if (::pipe2(wake_, O_CLOEXEC | O_NONBLOCK) != 0) wake_[0] = wake_[1] = -1;
  thread_ = std::thread([this] { drain(); });
}

LingeringCloses::~LingeringCloses() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  arrived_.notify_all();
  if (wake_[1] >= 0) (void)!::write(wake_[1], "x", 1);
  thread_.join();
  for (const int end : wake_)
    if (end >= 0) ::close(end);
}

void LingeringCloses::close(socket_t socket, std::chrono::steady_clock::duration allowance) {
  ::shutdown(socket, SHUT_WR);
  {
    std::lock_guard lock(mutex_);
    if (!stopping_ && added_.size() < kMaxLingering) {
      added_.push_back({socket, std::chrono::steady_clock::now() + allowance});
      if (wake_[1] >= 0) (void)!::write(wake_[1], "x", 1);
      arrived_.notify_one();
      return;
    }
  }
  close_now(socket);
}

bool LingeringCloses::keep_draining(Lingering& lingering) {
  char sink[16384];
  for (;;) {
    const ssize_t n = ::recv(lingering.socket, sink, sizeof sink, MSG_DONTWAIT);
    if (n < 0) return errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR;
    if (n == 0) return false;
    lingering.drained += static_cast<std::size_t>(n);
    if (lingering.drained >= kLingerBytes) return false;
  }
}

void LingeringCloses::drain() {
  std::vector<Lingering> lingering;
  std::vector<pollfd> watched;
  for (;;) {
    {
      std::unique_lock lock(mutex_);
      if (lingering.empty()) arrived_.wait(lock, [this] { return stopping_ || !added_.empty(); });
      if (stopping_) break;
      const std::size_t room = kMaxLingering - std::min(kMaxLingering, lingering.size());
      for (std::size_t k = 0; k < added_.size(); ++k)
        k < room ? lingering.push_back(added_[k]) : close_now(added_[k].socket);
      added_.clear();
    }
    const auto now = std::chrono::steady_clock::now();
    auto next = now + std::chrono::seconds(1);
    watched.assign({{wake_[0], POLLIN, 0}});
    for (const auto& each : lingering) {
      watched.push_back({each.socket, POLLIN, 0});
      next = std::min(next, each.deadline);
    }
    const auto wait = std::chrono::ceil<std::chrono::milliseconds>(next - now);
    ::poll(watched.data(), watched.size(), static_cast<int>(std::max<std::int64_t>(0, wait.count())));
    char emptied[64];
    while (wake_[0] >= 0 && ::read(wake_[0], emptied, sizeof emptied) > 0) {
    }
    const auto after = std::chrono::steady_clock::now();
    std::size_t kept = 0;
    for (std::size_t k = 0; k < lingering.size(); ++k) {
      const bool readable = watched[k + 1].revents != 0;
      if (after < lingering[k].deadline && (!readable || keep_draining(lingering[k])))
        lingering[kept++] = lingering[k];
      else
        close_now(lingering[k].socket);
    }
    lingering.resize(kept);
  }
  for (const auto& each : lingering) close_now(each.socket);
  std::lock_guard lock(mutex_);
  for (const auto& each : added_) close_now(each.socket);
  added_.clear();
}

}  // namespace aerobreak
