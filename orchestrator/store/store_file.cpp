#include "orchestrator/store/store_file.hpp"

#include <sys/stat.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <set>

#include "orchestrator/store/migrations.hpp"
#include "orchestrator/store/sqlite_database.hpp"

namespace aerobreak {
namespace {

// The tables of the first schema version: every aerobreak store has them.
constexpr std::array<const char*, 7> kCoreTables{"studies",  "jobs",    "cases",    "study_cases",
                                                 "attempts", "results", "fragments"};

StoreFileState refused(StoreFileState::Kind kind, int version, const std::filesystem::path& file,
                       const std::string& what) {
  return {kind, version, "the file " + file.string() + " " + what};
}

std::string listed(const std::set<std::string>& tables) {
  std::string text;
  std::size_t shown = 0;
  for (const auto& table : tables) {
    if (shown++ == 5) return text + ", ...";
    text += (text.empty() ? "" : ", ") + table;
  }
  return text;
}

StoreFileState inspect_database(const std::filesystem::path& file) {
  SqliteDatabase db(file, SqliteDatabase::Mode::read_only);
  auto version_row = db.prepare("PRAGMA user_version");
  version_row.step();
  const int version = static_cast<int>(version_row.integer(0));
  std::set<std::string> tables;
  auto table_rows = db.prepare("SELECT name FROM sqlite_master WHERE type = 'table' AND name NOT LIKE 'sqlite_%'");
  while (table_rows.step()) tables.insert(table_rows.text(0));

  const int latest = latest_store_version();
  if (version == 0 && tables.empty()) return {StoreFileState::Kind::empty, 0, {}};
  std::string missing;
  for (const char* table : kCoreTables)
    if (!tables.contains(table)) missing += (missing.empty() ? "" : ", ") + std::string(table);
  if (version == 0 || !missing.empty())
    return refused(StoreFileState::Kind::foreign, version, file,
                   "is an SQLite database of another program, not an aerobreak store (schema version " +
                       std::to_string(version) + ", tables " + listed(tables) +
                       (missing.empty() ? std::string() : "; no " + missing) + ")");
  if (version > latest)
    return refused(StoreFileState::Kind::newer, version, file,
                   "is a store of a newer aerobreak (schema version " + std::to_string(version) +
                       "; this aerobreak knows versions up to " + std::to_string(latest) +
                       "): use that aerobreak, or a newer one, with it");
  return {StoreFileState::Kind::store, version, {}};
}

}  // namespace

StoreFileState inspect_store_file(const std::filesystem::path& file) {
  struct stat status {};
  if (::stat(file.c_str(), &status) != 0) {
    if (errno == ENOENT) return {};
    return refused(StoreFileState::Kind::foreign, 0, file, std::string("cannot be examined: ") + std::strerror(errno));
  }
  if (!S_ISREG(status.st_mode)) return refused(StoreFileState::Kind::foreign, 0, file, "is not a regular file");
  if (status.st_size == 0) return {StoreFileState::Kind::empty, 0, {}};
  try {
    return inspect_database(file);
  } catch (const SqliteError& error) {
    if ((error.code() & 0xff) == SQLITE_NOTADB)
      return refused(StoreFileState::Kind::foreign, 0, file, "is not an SQLite database, nor empty");
    return refused(StoreFileState::Kind::foreign, 0, file, std::string("cannot be read as a store: ") + error.what());
  }
}

}  // namespace aerobreak
