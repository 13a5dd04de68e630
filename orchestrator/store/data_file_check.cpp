#include "orchestrator/store/data_file_check.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>

#include "orchestrator/study/sha256.hpp"

namespace aerobreak {
namespace {

// Checksums kept at most; past it the memory starts afresh (a re-read costs time, not correctness).
constexpr std::size_t kMaxRemembered = 100000;

std::int64_t nanoseconds(const timespec& time) { return std::int64_t{time.tv_sec} * 1000000000 + time.tv_nsec; }

}  // namespace

std::string_view to_string(DataFileState state) {
  switch (state) {
    case DataFileState::ok:
      return "ok";
    case DataFileState::missing:
      return "missing";
    case DataFileState::damaged:
      return "damaged";
    case DataFileState::unverified:
      return "unverified";
  }
  return "unverified";
}

DataFileCheck DataFileChecker::check(const std::string& path, const DataFileDigest& expected) {
  struct stat status {};
  if (::stat(path.c_str(), &status) != 0)
    return {errno == ENOENT ? DataFileState::missing : DataFileState::damaged,
            "cannot find " + path + ": " + std::strerror(errno)};
  if (expected.size >= 0 && status.st_size != expected.size)
    return {DataFileState::damaged, path + " has " + std::to_string(status.st_size) + " bytes; it had " +
                                        std::to_string(expected.size) + " when it was written"};
  if (expected.sha256.empty()) return {DataFileState::unverified, {}};

  const Seen now{
      status.st_dev, status.st_ino, status.st_size, nanoseconds(status.st_mtim), nanoseconds(status.st_ctim), {}};
  std::string sha256;
  {
    std::lock_guard lock(mutex_);
    const auto found = seen_.find(path);
    if (found != seen_.end() && found->second.device == now.device && found->second.inode == now.inode &&
        found->second.size == now.size && found->second.modified_ns == now.modified_ns &&
        found->second.changed_ns == now.changed_ns)
      sha256 = found->second.sha256;
  }
  if (sha256.empty()) {
    try {
      sha256 = sha256_hex_of_file(path);
    } catch (const std::exception& error) {
      return {DataFileState::damaged, error.what()};
    }
    std::lock_guard lock(mutex_);
    if (seen_.size() >= kMaxRemembered) seen_.clear();
    Seen remembered = now;
    remembered.sha256 = sha256;
    seen_[path] = std::move(remembered);
  }
  if (sha256 != expected.sha256)
    return {DataFileState::damaged,
            path + " is not the file written: its SHA-256 is " + sha256 + ", not " + expected.sha256};
  return {DataFileState::ok, {}};
}

}  // namespace aerobreak
