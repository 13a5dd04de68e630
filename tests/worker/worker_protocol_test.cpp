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
                        {"document", document}, {"wall_time", 2.5},        {"data_file", "/data/c.h5"}};
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
