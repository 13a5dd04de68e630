// DataFileChecker (docs/ORCHESTRATOR.md, Store, "Data files checked"): a case's data file against
// the size and SHA-256 its worker
// recorded. The reference digest is FIPS 180-4's example, checked with `sha256sum`:
//   printf abc | sha256sum   -> ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad
#include <catch2/catch.hpp>

#include <chrono>
#include <fstream>
#include <thread>

#include "orchestrator/store/data_file_check.hpp"
#include "tests/support/scratch_directory.hpp"

namespace aerobreak::testing {
namespace {

constexpr const char* kAbcSha256 = "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad";

void write_file(const std::filesystem::path& file, const std::string& bytes) {
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
}

}  // namespace

TEST_CASE("A data file is ok, missing, damaged in size or content, or unverified without a digest", "[store]") {
  ScratchDirectory scratch("data-file-check");
  const auto file = scratch.path() / "case.h5";
  write_file(file, "abc");
  DataFileChecker checker;
  const DataFileDigest recorded{3, kAbcSha256};
  CHECK(checker.check(file.string(), recorded).state == DataFileState::ok);
  CHECK(checker.check(file.string(), {}).state == DataFileState::unverified);

  // Same size, other bytes: only the checksum tells, and the remembered one must not hide it. The
  // kernel stamps files from a coarse clock (a few ms): the rewrite must get a later stamp.
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  write_file(file, "abd");
  const auto changed = checker.check(file.string(), recorded);
  CHECK(changed.state == DataFileState::damaged);
  CHECK_THAT(changed.problem, Catch::Contains("SHA-256"));

  write_file(file, "abcd");
  const auto longer = checker.check(file.string(), recorded);
  CHECK(longer.state == DataFileState::damaged);
  CHECK_THAT(longer.problem, Catch::Contains("has 4 bytes; it had 3"));

  std::filesystem::remove(file);
  CHECK(checker.check(file.string(), recorded).state == DataFileState::missing);
  write_file(file, "abc");
  CHECK(checker.check(file.string(), recorded).state == DataFileState::ok);
}

}  // namespace aerobreak::testing
