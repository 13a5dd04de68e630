// One case run in-process as a worker rank runs it: its result document, its wall-time limit and
// its bulk HDF5 file.
#include <catch2/catch.hpp>

#include <hdf5.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <optional>
#include <system_error>
#include <vector>

#include "engine/impact/impact_case.hpp"
#include "engine/impact/impact_result.hpp"
#include "engine/io/h5md_reader.hpp"
#include "engine/io/hdf5_datasets.hpp"
#include "engine/io/hdf5_handle.hpp"
#include "tests/support/scratch_directory.hpp"
#include "orchestrator/worker/case_data_file.hpp"
#include "orchestrator/worker/case_runner.hpp"
#include "worker_cases.hpp"

using namespace aerobreak;
using Catch::Matchers::Contains;

namespace {

std::vector<std::int32_t> read_fragment_index(const std::filesystem::path& file) {
  const Hdf5Handle h5 = checked_handle(H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "open", file);
  const Hdf5Handle value = open_dataset(h5.get(), "particles/all/fragment/value");
  const std::vector<hsize_t> shape = dataset_shape(value.get());
  REQUIRE(shape.size() == 2);
  REQUIRE(shape[0] == 1);
  std::vector<std::int32_t> index(shape[1]);
  read_dataset(value.get(), H5T_NATIVE_INT32, index.data());
  return index;
}

// Files being written (".partial") left in `folder`.
std::size_t partial_files(const std::filesystem::path& folder) {
  return std::count_if(std::filesystem::directory_iterator(folder), std::filesystem::directory_iterator(),
                       [](const auto& entry) { return entry.path().extension() == ".partial"; });
}

}  // namespace

TEST_CASE("run_case returns a valid result document and its wall-clock seconds") {
  const CaseRunOutcome outcome = run_case(testing::tiny_case(), 0.0, {});
  INFO(describe(validate_result(outcome.result)));
  CHECK(validate_result(outcome.result).empty());
  CHECK(outcome.result["dimensionless"]["primaries"] == 16);
  CHECK(outcome.data_file.empty());
  CHECK(outcome.seconds > 0.0);
}

TEST_CASE("run_case refuses an invalid document with a CaseError naming the field") {
  auto document = testing::tiny_case();
  document["impact"]["speed"] = -1.0;
  CHECK_THROWS_AS(run_case(document, 0.0, {}), CaseError);
  CHECK_THROWS_WITH(run_case(document, 0.0, {}), Contains("/impact/speed"));
}

TEST_CASE("A short wall time stops a long case within a bounded time") {
  const testing::ScratchDirectory scratch("case_runner");
  const auto data_file = scratch.path() / "stopped.h5";
  const auto start = std::chrono::steady_clock::now();
  // About 30 s of work without the limit.
  CHECK_THROWS_AS(run_case(testing::slow_case(1e6), 0.3, data_file), WallTimeExceeded);
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  CHECK(elapsed < 2.0);
  // Neither a file under the name nor a half-written one is left behind.
  CHECK_FALSE(std::filesystem::exists(data_file));
  CHECK(partial_files(scratch.path()) == 0);
}

TEST_CASE("The bulk file holds the first and last states and each primary's final fragment") {
  const testing::ScratchDirectory scratch("case_runner");
  const auto data_file = scratch.path() / "new" / "folder" / "case.h5";
  const CaseRunOutcome outcome = run_case(testing::tiny_case(), 0.0, data_file);
  CHECK(outcome.data_file == data_file.string());
  REQUIRE(std::filesystem::exists(data_file));
  CHECK(partial_files(data_file.parent_path()) == 0);

  REQUIRE(h5md_frame_count(data_file) == 2);
  const H5mdFrame first = read_h5md_frame(data_file, 0);
  const H5mdFrame last = read_h5md_frame(data_file, 1);
  CHECK(first.position.size() == 16);
  CHECK(first.step == 0);
  CHECK(last.step == outcome.result["run"]["steps"]);

  // The index follows the result's fragment list (largest first): sizes agree fragment by fragment.
  const std::vector<std::int32_t> index = read_fragment_index(data_file);
  REQUIRE(index.size() == 16);
  const auto& fragments = outcome.result["fragments"]["list"];
  REQUIRE(fragments.size() > 1);  // the tiny case breaks up
  for (std::size_t f = 0; f < fragments.size(); ++f)
    CHECK(std::count(index.begin(), index.end(), static_cast<std::int32_t>(f)) == fragments[f]["size"]);
}

TEST_CASE("An attempt that still holds its half-written file open does not stop the case's next attempt") {
  // A rank given up mid-case (stopped, or its node cut off) keeps its file open, and HDF5's lock on
  // it, while the case runs again elsewhere into the same data file.
  const testing::ScratchDirectory scratch("case_runner");
  const auto data_file = scratch.path() / "cases" / "case.h5";
  std::optional<CaseDataFile> given_up(std::in_place, data_file);
  const CaseRunOutcome outcome = run_case(testing::tiny_case(), 0.0, data_file);
  REQUIRE(std::filesystem::exists(data_file));
  CHECK(h5md_frame_count(data_file) == 2);
  CHECK(std::filesystem::file_size(data_file) == outcome.data_file_size);
  CHECK(partial_files(data_file.parent_path()) == 1);  // the given-up attempt's own
  given_up.reset();
  CHECK(partial_files(data_file.parent_path()) == 0);
  CHECK(std::filesystem::file_size(data_file) == outcome.data_file_size);
}
