#pragma once
#include <cstdint>
#include <mutex>
#include <string>
#include <unordered_map>

#include "orchestrator/store/store_types.hpp"

namespace aerobreak {

// How a case's bulk data file compares with the size and SHA-256 its worker reported.
enum class DataFileState { ok, missing, damaged, unverified };
std::string_view to_string(DataFileState state);

struct DataFileCheck {
  DataFileState state = DataFileState::unverified;
  std::string problem;  // what is wrong; empty when ok
};

// Checks data files against their recorded size and SHA-256 (missing: no file; damaged: another
// size or checksum, or unreadable; unverified: no checksum was recorded, as for results stored
// before checksums were). A file is checksummed again only when its identity on disk changes
// (device, inode, size, modification or status-change time), so that reading a case many times
// costs a stat, not a read of the file. Safe to use from several threads.
class DataFileChecker {
 public:
  DataFileCheck check(const std::string& path, const DataFileDigest& expected);

 private:
  struct Seen {
    std::uint64_t device = 0, inode = 0;
    std::int64_t size = 0, modified_ns = 0, changed_ns = 0;
    std::string sha256;
  };

  std::mutex mutex_;
  std::unordered_map<std::string, Seen> seen_;
};

}  // namespace aerobreak
