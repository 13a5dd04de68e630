#pragma once
#include <filesystem>
#include <stdexcept>
#include <string>

namespace aerobreak {

// What a file named as a store holds, found without changing it: read through a read-only SQLite
// connection, after a check that it is a regular file, before anything locks, migrates or switches
// it to WAL.
struct StoreFileState {
  enum class Kind {
    absent,   // no file: a new store is made there
    empty,    // an empty file, or an SQLite database without tables: it becomes a store
    store,    // an aerobreak store of `version` (at most this aerobreak's)
    newer,    // an aerobreak store of a schema version above this aerobreak's
    foreign,  // anything else: not SQLite, or another program's database
  };
  Kind kind = Kind::absent;
  int version = 0;      // PRAGMA user_version, where it could be read
  std::string problem;  // for newer and foreign: what the file is, naming it
};

StoreFileState inspect_store_file(const std::filesystem::path& file);

// A file that an orchestrator or reader refuses as its store; nothing of it was changed.
class StoreFileRefused : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace aerobreak
