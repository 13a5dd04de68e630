// Storage faults (docs/ORCHESTRATOR.md, "What happens when things fail"): a store whose disk fills
// up mid-study, and a second
// orchestrator started on a store that one runs. Real `aerobreak serve`, a real SQLite file on a
// real (small) file system, real mpirun workers.
#include <sys/mount.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>

#include "tests/orchestrator/service_process.hpp"
#include "tests/support/run_command.hpp"

namespace aerobreak::testing {
namespace {

// A tmpfs of `size` mounted at `directory` for the test's lifetime (needs root, as CI has).
class SmallFileSystem {
 public:
  SmallFileSystem(const std::filesystem::path& directory, const std::string& size) : directory_(directory) {
    std::filesystem::create_directories(directory_);
    mounted_ = ::mount("tmpfs", directory_.c_str(), "tmpfs", 0, ("size=" + size).c_str()) == 0;
    error_ = mounted_ ? "" : std::strerror(errno);
  }
  ~SmallFileSystem() {
    if (mounted_) ::umount2(directory_.c_str(), MNT_DETACH);
  }
  bool mounted() const { return mounted_; }
  const std::string& error() const { return error_; }

  // Writes a file until the file system is full.
  void fill(const std::filesystem::path& file) {
    std::FILE* out = std::fopen(file.c_str(), "wb");
    REQUIRE(out);
    const std::string block(1 << 16, 'x');
    while (std::fwrite(block.data(), 1, block.size(), out) == block.size() && std::fflush(out) == 0) {
    }
    std::fclose(out);
  }

 private:
  std::filesystem::path directory_;
  bool mounted_ = false;
  std::string error_;
};

Json cases_of(const ServiceProcess& service, std::int64_t study) {
  return service.get("/api/studies/" + std::to_string(study) + "/cases?limit=1000").at("items");
}

bool no_case_failed(const ServiceProcess& service, std::int64_t study) {
  for (const auto& record : cases_of(service, study))
    if (record.at("failures") != 0 || record.at("status") == "failed") return false;
  return true;
}

}  // namespace

TEST_CASE(
    "A full disk under the store fails no case, keeps serve up, shows in health, and the study finishes once "
    "space returns",
    "[service][crash]") {
  if (::geteuid() != 0) {
    WARN("skipped: mounting a small tmpfs needs root (CI runs as root)");
    return;
  }
  ScratchDirectory scratch("disk-full");
  SmallFileSystem disk(scratch.path() / "disk", "16m");
  INFO("mount tmpfs: " << disk.error());
  REQUIRE(disk.mounted());
  ServiceProcess service(scratch.path(), {}, scratch.path() / "disk" / "store.sqlite");
  const auto study = submit(service, slow_study("disk full", 8)).at("id").get<std::int64_t>();
  // Filled once cases are being handed out and committed: results, claims and data files all meet it.
  REQUIRE(eventually(
      [&] { return service.get("/api/studies/" + std::to_string(study) + "/progress").at("counts").at("done") >= 1; },
      60s));
  const auto filler = scratch.path() / "disk" / "filler";
  disk.fill(filler);

  Json health;
  REQUIRE(eventually(
      [&] {
        health = service.get("/api/health");
        return health.at("status") == "degraded" && !health.at("scheduler").at("storage_fault").is_null();
      },
      60s));
  INFO(health.dump());
  CHECK(health.at("scheduler").at("storage_fault").at("error").is_string());
  CHECK(no_case_failed(service, study));
  CHECK_FALSE(study_complete(service, study));

  std::filesystem::remove(filler);
  REQUIRE(eventually([&] { return study_complete(service, study); }, 120s));
  CHECK(no_case_failed(service, study));
  CHECK(service.get("/api/studies/" + std::to_string(study) + "/progress").at("counts").at("done") == 8);
  CHECK(eventually([&] { return service.get("/api/health").at("status") == "ok"; }, 20s));
  CHECK(service.get("/api/health").at("scheduler").at("storage_fault").is_null());
}

TEST_CASE("A second orchestrator on a store in use is refused and the first runs on undisturbed", "[service][crash]") {
  ScratchDirectory scratch("store-lock");
  ServiceProcess service(scratch.path());
  const auto study = submit(service, slow_study("store lock", 4)).at("id").get<std::int64_t>();
  REQUIRE(eventually(
      [&] {
        const auto job = service.get("/api/health").at("scheduler").at("job");
        return job.is_object() && job.at("in_flight").get<int>() > 0;
      },
      30s));

  // `timeout`: before the fix the second service would run on for good.
  const std::string in_use = "is in use by process " + std::to_string(service.pid());
  const auto second = run_command("timeout 20 " + std::string(AEROBREAK_BINARY) + " serve --port 0 --store " +
                                  service.store_file().string());
  CHECK(second.exit_code == 1);
  CHECK_THAT(second.text, Catch::Contains(in_use));
  const auto study_file = scratch.write("again.study.json", slow_study("store lock", 4).dump());
  const auto run = run_command("timeout 20 " + std::string(AEROBREAK_BINARY) + " run " + study_file.string() +
                               " --port 0 --store " + service.store_file().string());
  CHECK(run.exit_code == 1);
  CHECK_THAT(run.text, Catch::Contains(in_use));

  REQUIRE(eventually([&] { return study_complete(service, study); }, 120s));
  for (const auto& record : cases_of(service, study)) {
    CHECK(record.at("status") == "done");
    CHECK(record.at("attempts") == 1);
  }
  // The lock dies with its process: a restart after SIGKILL takes the store at once.
  CHECK(service.kill(SIGKILL) == 128 + SIGKILL);
  ServiceProcess restarted(scratch.path());
  CHECK(restarted.get("/api/studies/" + std::to_string(study) + "/progress").at("counts").at("done") == 4);
}

}  // namespace aerobreak::testing
