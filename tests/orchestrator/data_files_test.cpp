// Each case's HDF5 file is checked against the size and SHA-256 its worker recorded
// (docs/ORCHESTRATOR.md, Store, "Data files checked"): a damaged or deleted file shows in the case;
// submitting the study again reports it, keeps its result, and recomputes it when asked. A store
// moved or copied with its data folder finds its files. Also the receipt of a study submitted again
// when all its cases are done.
#include <fstream>

#include "tests/orchestrator/service_process.hpp"
#include "tests/support/run_command.hpp"

namespace aerobreak::testing {
namespace {

Json case_detail(const ServiceProcess& service, std::int64_t id) {
  return service.get("/api/cases/" + std::to_string(id));
}

// The status of a download of the case's file.
int download_status(const ServiceProcess& service, std::int64_t id) {
  auto client = service.client();
  const auto response = client.Get("/api/cases/" + std::to_string(id) + "/data");
  REQUIRE(response);
  return response->status;
}

void flip_a_byte(const std::string& file) {
  std::fstream data(file, std::ios::in | std::ios::out | std::ios::binary);
  REQUIRE(data);
  data.seekg(0, std::ios::end);
  const auto middle = data.tellg() / 2;
  data.seekg(middle);
  char byte = 0;
  data.read(&byte, 1);
  data.seekp(middle);
  byte = static_cast<char>(~byte);
  data.write(&byte, 1);
}

}  // namespace

TEST_CASE("A damaged or deleted case file shows in the case, resubmitting reports it and recomputes it when asked",
          "[service]") {
  ScratchDirectory scratch("data-files");
  ServiceProcess service(scratch.path());
  const Json study_document = small_study("data files", {0.01, 0.05}, 1);
  const auto study = submit(service, study_document).at("id").get<std::int64_t>();
  REQUIRE(eventually([&] { return study_complete(service, study); }, 60s));

  const auto cases = service.get("/api/studies/" + std::to_string(study) + "/cases").at("items");
  REQUIRE(cases.size() == 2);
  const auto damaged_id = cases[0].at("id").get<std::int64_t>();
  const auto deleted_id = cases[1].at("id").get<std::int64_t>();
  const auto damaged = case_detail(service, damaged_id);
  const std::string damaged_file = damaged.at("data_file").get<std::string>();
  const std::string deleted_file = case_detail(service, deleted_id).at("data_file").get<std::string>();
  REQUIRE(damaged.at("data_file_check").at("state") == "ok");
  CHECK(damaged.at("data_file_check").at("size") == std::filesystem::file_size(damaged_file));
  CHECK(damaged.at("data_file_check").at("sha256").get<std::string>().size() == 64);
  CHECK(download_status(service, damaged_id) == 200);

  flip_a_byte(damaged_file);
  std::filesystem::remove(deleted_file);
  const auto damaged_check = case_detail(service, damaged_id).at("data_file_check");
  CHECK(damaged_check.at("state") == "damaged");
  CHECK_THAT(damaged_check.at("problem").get<std::string>(), Catch::Contains("SHA-256"));
  CHECK(case_detail(service, deleted_id).at("data_file_check").at("state") == "missing");
  // Read through the download, the damaged file is refused rather than served as the case's.
  CHECK(download_status(service, damaged_id) == 409);
  CHECK(download_status(service, deleted_id) == 404);

  // Submitted again: the lost files are reported, and the results kept and served.
  const auto reported = submit(service, study_document, 200);
  CHECK(reported.at("data_files_lost") == 2);
  CHECK(reported.at("recomputed") == 0);
  CHECK(reported.at("already_done") == 2);
  for (const auto id : {damaged_id, deleted_id}) {
    const auto detail = case_detail(service, id);
    CHECK(detail.at("status") == "done");
    CHECK(detail.at("result").is_object());
  }
  CHECK(service.get("/api/studies/" + std::to_string(study) + "/results").at("items").size() == 2);

  // Asked for, they are computed again.
  const auto receipt = submit(service, study_document, 200, "?recompute_data_files=true");
  CHECK(receipt.at("recomputed") == 2);
  CHECK(receipt.at("data_files_lost") == 2);
  REQUIRE(eventually([&] { return study_complete(service, study); }, 60s));
  for (const auto id : {damaged_id, deleted_id}) {
    const auto detail = case_detail(service, id);
    CHECK(detail.at("status") == "done");
    CHECK(detail.at("data_file_check").at("state") == "ok");
    CHECK(detail.at("attempt_history").size() == 2);
    CHECK(download_status(service, id) == 200);
  }
  // Every case done: a resubmission says so.
  const auto again = submit(service, study_document, 200);
  CHECK(again.at("already_done") == 2);
  CHECK(again.at("recomputed") == 0);
}

TEST_CASE("A store moved or copied with its data folder finds every data file: nothing is recomputed or lost",
          "[service]") {
  ScratchDirectory scratch("moved-store");
  const auto first = scratch.path() / "first";
  std::filesystem::create_directories(first);
  const auto study_file = scratch.write("moved.study.json", small_study("moved", {0.01, 0.05}, 1).dump());
  const std::string run =
      "timeout 120 " + std::string(AEROBREAK_BINARY) + " run " + study_file.string() + " --ranks 1 --port 0 --store ";
  REQUIRE(run_command(run + (first / "s.sqlite").string()).exit_code == 0);

  // Moved: the store and its data folder (s.data) together.
  const auto moved = scratch.path() / "moved";
  std::filesystem::rename(first, moved);
  const auto again = run_command(run + (moved / "s.sqlite").string());
  INFO(again.text);
  CHECK(again.exit_code == 0);
  CHECK_THAT(again.text, Catch::Contains("(2 already done)"));
  CHECK_THAT(again.text, !Catch::Contains("computed again") && !Catch::Contains("lost"));

  // Copied beside it: the copy serves its own files.
  const auto copy = scratch.path() / "copy";
  std::filesystem::copy(moved, copy, std::filesystem::copy_options::recursive);
  ServiceProcess service(scratch.path(), {}, copy / "s.sqlite");
  const auto cases = service.get("/api/studies/1/cases").at("items");
  REQUIRE(cases.size() == 2);
  for (const auto& listed : cases) {
    const auto id = listed.at("id").get<std::int64_t>();
    const auto detail = case_detail(service, id);
    CHECK_THAT(detail.at("data_file").get<std::string>(), Catch::StartsWith((copy / "s.data").string()));
    CHECK(detail.at("data_file_check").at("state") == "ok");
    CHECK(download_status(service, id) == 200);
  }
}

}  // namespace aerobreak::testing
