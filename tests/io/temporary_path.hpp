#pragma once
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <random>
#include <string>
#include <system_error>

namespace aerobreak::test {

// A unique file name in the system's temporary directory; the file (if any) is removed when the
// object goes out of scope.
class TemporaryPath {
 public:
  explicit TemporaryPath(const std::string& suffix) {
    static std::atomic<unsigned> counter{0};
    const std::string name = "aerobreak_io_test_" + std::to_string(::getpid()) + "_" +
                             std::to_string(std::random_device{}()) + "_" + std::to_string(counter++) + suffix;
    path_ = std::filesystem::temp_directory_path() / name;
  }
  TemporaryPath(const TemporaryPath&) = delete;
  TemporaryPath& operator=(const TemporaryPath&) = delete;
  ~TemporaryPath() {
    std::error_code ignored;
    std::filesystem::remove(path_, ignored);
  }

  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace aerobreak::test
