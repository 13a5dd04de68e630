// One orchestrator per store (docs/ORCHESTRATOR.md, `STORE.lock`): a Store holds the store's lock while it lives.
#include <sys/wait.h>
#include <unistd.h>

#include "orchestrator/store/migrations.hpp"
#include "tests/store/store_support.hpp"

namespace aerobreak {

TEST_CASE("A second Store on a file in use is refused, naming the holder, and the lock ends with the first",
          "[store]") {
  testing::TemporaryStoreFile file("lock");
  {
    Store first(file.path());
    CHECK_THROWS_AS(Store(file.path()), StoreInUse);
    CHECK_THROWS_WITH(Store(file.path()), Catch::Contains("is in use by process " + std::to_string(::getpid())));
  }
  Store again(file.path());
  CHECK(again.schema_version() == latest_store_version());
}

TEST_CASE("A process that dies holding a store leaves no lock behind", "[store]") {
  testing::TemporaryStoreFile file("lock-crash");
  const pid_t child = ::fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    Store held(file.path());
    ::_exit(0);  // no destructor runs: as if killed
  }
  int status = 0;
  REQUIRE(::waitpid(child, &status, 0) == child);
  Store store(file.path());
  CHECK(store.schema_version() == latest_store_version());
}

}  // namespace aerobreak
