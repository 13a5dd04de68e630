#pragma once
#include <httplib.h>

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <thread>
#include <vector>

namespace aerobreak {

// Connections closed before their request was read whole (refused early, or cut off as too slow)
// are closed as RFC 9112 9.6 asks: FIN first, then what the client still sends is read and
// dropped until it closes or `allowance` passes (at most 4 MiB), so that closing with unread
// bytes does not send a reset that destroys the answer before the client reads it. One thread
// drains them all: with a thread each for 2 s, slow senders cut off by the hundred a second held
// every connection thread and queued /api/health behind them. At most kMaxLingering at once;
// beyond, a connection is closed at once.
class LingeringCloses {
 public:
  static constexpr std::size_t kMaxLingering = 1024;

  LingeringCloses();
  ~LingeringCloses();
  LingeringCloses(const LingeringCloses&) = delete;
  LingeringCloses& operator=(const LingeringCloses&) = delete;

  // Takes the socket: it is closed here, now or once drained.
  void close(socket_t socket, std::chrono::steady_clock::duration allowance);

 private:
  struct Lingering {
    socket_t socket;
    std::chrono::steady_clock::time_point deadline;
    std::size_t drained = 0;
  };

  void drain();
  // Reads what `lingering` has; false once it is to be closed (its peer closed, or it sent too much).
  static bool keep_draining(Lingering& lingering);

  std::mutex mutex_;
  std::condition_variable arrived_;
  std::vector<Lingering> added_;  // handed over, not yet polled
  bool stopping_ = false;
  int wake_[2] = {-1, -1};  // a pipe that ends the drain thread's poll when one is added
  std::thread thread_;
};

}  // namespace aerobreak
