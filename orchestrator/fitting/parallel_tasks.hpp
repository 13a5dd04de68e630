#pragma once
#include <algorithm>
#include <atomic>
#include <functional>
#include <thread>
#include <vector>

namespace aerobreak {

// Runs independent tasks on every core (each thread takes the next task as it finishes one) and
// returns their results in task order. Fits of one study are independent of each other.
template <typename Result>
std::vector<Result> run_in_parallel(const std::vector<std::function<Result()>>& tasks) {
  std::vector<Result> results(tasks.size());
  std::atomic<std::size_t> next{0};
  const auto work = [&] {
    for (std::size_t i = next++; i < tasks.size(); i = next++) results[i] = tasks[i]();
  };
  const std::size_t threads = std::min<std::size_t>(std::max(1u, std::thread::hardware_concurrency()), tasks.size());
  std::vector<std::thread> pool;
  for (std::size_t t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (auto& thread : pool) thread.join();
  return results;
}

}  // namespace aerobreak
