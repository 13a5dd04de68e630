#pragma once
#include <filesystem>
#include <string>

#include "tests/support/scratch_directory.hpp"

namespace aerobreak::test {

// A unique file name, ending in `suffix`, in a scratch directory of its own; the file (if any) is
// removed with the directory when the object goes out of scope.
class TemporaryPath {
 public:
  explicit TemporaryPath(const std::string& suffix)
      : directory_("io_test"), path_(directory_.path() / ("file" + suffix)) {}

  const std::filesystem::path& path() const { return path_; }

 private:
  testing::ScratchDirectory directory_;
  std::filesystem::path path_;
};

}  // namespace aerobreak::test
