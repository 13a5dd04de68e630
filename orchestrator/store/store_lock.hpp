#pragma once
#include <filesystem>
#include <stdexcept>

namespace aerobreak {

// Another process holds the store.
class StoreInUse : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The exclusive right to write a store, held while the object lives: flock(2) on STORE.lock beside
// it. The kernel drops the lock when the process ends, however it ends, so that a crash leaves
// nothing behind that blocks a restart. The lock file holds the holder's pid, for the message a
// second process gets. The descriptor is close-on-exec: worker jobs do not inherit the lock.
class StoreLock {
 public:
  // Throws StoreInUse when another open lock holds it, std::runtime_error when the lock file
  // cannot be opened.
  explicit StoreLock(const std::filesystem::path& store_file);
  ~StoreLock();
  StoreLock(const StoreLock&) = delete;
  StoreLock& operator=(const StoreLock&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace aerobreak
