#pragma once
#include <chrono>
#include <ctime>

namespace aerobreak {

// The time a stretch of work took: wall clock, and the CPU time of the calling thread. On a
// machine shared with other work the CPU time is the better measure of the work's own cost (the
// wall clock counts the time the thread waited for a core); docs/PERFORMANCE.md.
struct ElapsedTimes {
  double wall_seconds = 0.0;
  double cpu_seconds = 0.0;
};

// Started when constructed; elapsed() reads both clocks since then.
class RunClock {
 public:
  RunClock() : wall_start_(std::chrono::steady_clock::now()), cpu_start_(thread_cpu_seconds()) {}

  ElapsedTimes elapsed() const {
    return {std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start_).count(),
            thread_cpu_seconds() - cpu_start_};
  }

  static double thread_cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
  }

 private:
  std::chrono::steady_clock::time_point wall_start_;
  double cpu_start_;
};

}  // namespace aerobreak
