// The worker protocol's lines: one line per message behind the prefix, and every malformed line
// from the orchestrator either tied to its case or refused as a protocol error.
#include <catch2/catch.hpp>

#include <string>
#include <variant>

#include "orchestrator/worker/worker_protocol.hpp"

using namespace aerobreak;
using Json = nlohmann::ordered_json;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

TEST_CASE("A protocol line is the prefix, one compact JSON object and a newline") {
  const std::string line = protocol_line(failed_message(7, 2, 1, 0.5, FailureKind::wall_time, "first\nsecond"));
  CHECK_THAT(line, StartsWith("@aerobreak {\"type\":\"failed\","));
  CHECK(line.back() == '\n');
  CHECK(line.find('\n') == line.size() - 1);  // the newline in the error text is escaped
  const Json back = Json::parse(line.substr(kProtocolPrefix.size()));
  CHECK(back["kind"] == "wall_time");
  CHECK(back["error"] == "first\nsecond");
}

TEST_CASE("A message with invalid UTF-8 in a string is still sent") {
  const std::string line = protocol_line(protocol_error_message("bad byte \xff here"));
  CHECK_THAT(line, Contains("bad byte"));
  CHECK_NOTHROW(Json::parse(line.substr(kProtocolPrefix.size())));
}

TEST_CASE("A case message decodes to its assignment and back") {
  const Json document = {{"run", {{"time_limit", 1}}}};
  const Json message = {{"type", "case"},       {"case", 9007199254740993}, {"attempt", 3},
                        {"document", document}, {"wall_time", 2.5},         {"data_file", "/data/c.h5"}};
  std::string line = protocol_line(message);
  line.pop_back();  // the reader hands over lines without their '\n'
  const OrchestratorMessage decoded = decode_orchestrator_line(line);
  REQUIRE(std::holds_alternative<CaseAssignment>(decoded));
  const auto& a = std::get<CaseAssignment>(decoded);
  CHECK(a.case_id == 9007199254740993);
  CHECK(a.attempt == 3);
  CHECK(a.document == document);
  CHECK(a.wall_time == 2.5);
  CHECK(a.data_file == "/data/c.h5");
  CHECK(to_json(a) == message);
}

TEST_CASE("wall_time and data_file may be left out") {
  const auto decoded = decode_orchestrator_line(R"(@aerobreak {"type":"case","case":1,"attempt":0,"document":{}})");
  REQUIRE(std::holds_alternative<CaseAssignment>(decoded));
  CHECK(std::get<CaseAssignment>(decoded).wall_time == 0.0);
  CHECK(std::get<CaseAssignment>(decoded).data_file.empty());
}

TEST_CASE("A stop message decodes") {
  CHECK(std::holds_alternative<StopRequest>(decode_orchestrator_line(R"(@aerobreak {"type":"stop"})")));
}

TEST_CASE("Lines that cannot be tied to a case are protocol errors") {
  CHECK_THROWS_WITH(decode_orchestrator_line(R"({"type":"stop"})"), Contains("prefix"));
  CHECK_THROWS_WITH(decode_orchestrator_line("@aerobreak {\"type\":"), Contains("not JSON"));
  CHECK_THROWS_WITH(decode_orchestrator_line("@aerobreak [1,2]"), Contains("JSON object"));
  CHECK_THROWS_WITH(decode_orchestrator_line(R"(@aerobreak {"type":"pause"})"), Contains("unknown message type"));
  CHECK_THROWS_WITH(decode_orchestrator_line(R"(@aerobreak {"type":"case","attempt":0,"document":{}})"),
                    Contains("/case"));
  CHECK_THROWS_WITH(decode_orchestrator_line(R"(@aerobreak {"type":"case","case":1.5,"attempt":0,"document":{}})"),
                    Contains("/case"));
  CHECK_THROWS_WITH(decode_orchestrator_line(R"(@aerobreak {"type":"case","case":1,"attempt":-1,"document":{}})"),
                    Contains("/attempt"));
}

TEST_CASE("A case message with its case and attempt but bad fields is answered as that case") {
  const auto check_malformed = [](const std::string& line, const std::string& field) {
    const OrchestratorMessage decoded = decode_orchestrator_line(line);
    REQUIRE(std::holds_alternative<MalformedAssignment>(decoded));
    const auto& m = std::get<MalformedAssignment>(decoded);
    CHECK(m.case_id == 4);
    CHECK(m.attempt == 1);
    CHECK_THAT(m.error, Contains(field));
  };
  check_malformed(R"(@aerobreak {"type":"case","case":4,"attempt":1})", "/document");
  check_malformed(R"(@aerobreak {"type":"case","case":4,"attempt":1,"document":{},"wall_time":-1})", "/wall_time");
  check_malformed(R"(@aerobreak {"type":"case","case":4,"attempt":1,"document":{},"wall_time":"1"})", "/wall_time");
  check_malformed(R"(@aerobreak {"type":"case","case":4,"attempt":1,"document":{},"data_file":"out/c.h5"})",
                  "/data_file");
  check_malformed(R"(@aerobreak {"type":"case","case":4,"attempt":1,"document":{},"data_file":3})", "/data_file");
}

namespace {

// The typed message of a line a job writes, as the orchestrator reads it.
JobMessage job_message(const Json& message) {
  std::string line = protocol_line(message);
  line.pop_back();
  auto decoded = decode_job_line(line);
  REQUIRE(decoded);
  return std::move(*decoded);
}

}  // namespace

TEST_CASE("Every message a job writes decodes to its typed message with every field") {
  const auto ready = std::get<JobReady>(job_message(ready_message(2, {"n1", "n2"}, 4242, "1.2.3")));
  CHECK(ready.ranks == 2);
  CHECK(ready.hosts == std::vector<std::string>{"n1", "n2"});
  CHECK(ready.pid == 4242);
  CHECK(ready.version == "1.2.3");

  const auto started = std::get<CaseStarted>(job_message(started_message(9007199254740993, 3, 1, "n2")));
  CHECK(started.case_id == 9007199254740993);
  CHECK(started.attempt == 3);
  CHECK(started.rank == 1);
  CHECK(started.host == "n2");

  const Json result{{"outcome", "stick"}, {"retained_mass_fraction", 1.0}};
  const auto with_file =
      std::get<CaseResult>(job_message(result_message(5, 0, 1, 12.5, result, "/d/5.h5", 2048, "ab12")));
  CHECK(with_file.case_id == 5);
  CHECK(with_file.rank == 1);
  CHECK(with_file.seconds == 12.5);
  CHECK(with_file.result == nlohmann::json(result));
  CHECK(with_file.data_file == "/d/5.h5");
  CHECK(with_file.data_file_size == 2048);
  CHECK(with_file.data_file_sha256 == "ab12");
  const auto without_file = std::get<CaseResult>(job_message(result_message(5, 0, 1, 12.5, result, "")));
  CHECK(without_file.data_file.empty());
  CHECK(without_file.data_file_size == -1);
  CHECK(without_file.data_file_sha256.empty());

  for (const auto kind :
       {FailureKind::invalid, FailureKind::error, FailureKind::wall_time, FailureKind::storage, FailureKind::lost}) {
    const auto failed = std::get<CaseFailed>(job_message(failed_message(6, 2, 0, 0.5, kind, "why")));
    CHECK(failed.case_id == 6);
    CHECK(failed.attempt == 2);
    CHECK(failed.seconds == 0.5);
    CHECK(failed.kind == kind);
    CHECK(failed.error == "why");
  }
  CHECK(std::get<JobProtocolError>(job_message(protocol_error_message("not JSON"))).message == "not JSON");

  CHECK(std::holds_alternative<JobHeartbeat>(job_message(heartbeat_message())));
  const auto lost = std::get<RankLost>(job_message(rank_lost_message(3, "n3", 5, 61.5)));
  CHECK(lost.rank == 3);
  CHECK(lost.host == "n3");
  CHECK(lost.ranks == 5);
  CHECK(lost.silent_seconds == 61.5);
}

TEST_CASE("A job message with wrong fields is told apart: an answer for its case, or a line to log") {
  // An answer whose case and attempt can be read stays tied to them, with what is wrong.
  const auto no_result = std::get<UnreadableAnswer>(
      job_message({{"type", "result"}, {"case", 4}, {"attempt", 1}, {"rank", 0}, {"seconds", 1.0}, {"data_file", ""}}));
  CHECK(no_result.type == "result");
  CHECK(no_result.case_id == 4);
  CHECK(no_result.attempt == 1);
  CHECK_THAT(no_result.problem, Contains("/result"));
  const auto bad_kind = std::get<UnreadableAnswer>(job_message({{"type", "failed"},
                                                                {"case", 4},
                                                                {"attempt", 1},
                                                                {"rank", 0},
                                                                {"seconds", 1.0},
                                                                {"kind", "oom"},
                                                                {"error", "x"}}));
  CHECK_THAT(bad_kind.problem, Contains("/kind"));
  const auto negative = std::get<UnreadableAnswer>(job_message({{"type", "failed"},
                                                                {"case", 4},
                                                                {"attempt", 1},
                                                                {"rank", 0},
                                                                {"seconds", -1.0},
                                                                {"kind", "error"},
                                                                {"error", "x"}}));
  CHECK_THAT(negative.problem, Contains("/seconds"));
  // Without its case or attempt, or of no known type, it is only logged.
  CHECK_THAT(std::get<UnknownJobMessage>(job_message({{"type", "started"}, {"attempt", 1}})).problem,
             Contains("/case"));
  CHECK_THAT(std::get<UnknownJobMessage>(job_message({{"type", "paused"}})).problem, Contains("unknown message type"));
  CHECK_THAT(std::get<UnknownJobMessage>(job_message({{"type", "ready"}, {"ranks", 2}, {"hosts", {"n1"}}})).problem,
             Contains("/hosts"));
  CHECK_THAT(std::get<UnknownJobMessage>(job_message({{"type", "rank_lost"}, {"rank", 3}, {"host", "n3"}})).problem,
             Contains("/ranks"));
  // Lines that are not protocol: no prefix, or no JSON object after it.
  CHECK_FALSE(decode_job_line(R"({"type":"ready"})"));
  CHECK_FALSE(decode_job_line("@aerobreak {\"type\":"));
  CHECK_FALSE(decode_job_line("@aerobreak [1]"));
}
