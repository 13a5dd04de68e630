#pragma once
#include <memory>

#include "orchestrator/store/store.hpp"

namespace aerobreak {

// A reader connection borrowed from the store's pool for one query; returned on destruction.
class Store::ReadConnection {
 public:
  ReadConnection(Store& store, std::unique_ptr<SqliteDatabase> db) : store_(store), db_(std::move(db)) {}
  ReadConnection(const ReadConnection&) = delete;
  ReadConnection& operator=(const ReadConnection&) = delete;
  ~ReadConnection() {
    std::lock_guard lock(store_.pool_mutex_);
    store_.idle_readers_.push_back(std::move(db_));
  }
  SqliteDatabase& operator*() { return *db_; }
  SqliteDatabase* operator->() { return db_.get(); }

 private:
  Store& store_;
  std::unique_ptr<SqliteDatabase> db_;
};

}  // namespace aerobreak
