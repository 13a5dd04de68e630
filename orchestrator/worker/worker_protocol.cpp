#include "orchestrator/worker/worker_protocol.hpp"

#include <cmath>
#include <filesystem>
#include <limits>

namespace aerobreak {
namespace {

using Json = nlohmann::ordered_json;

// Enough of an offending line to recognise it in a log, not a whole case document.
std::string excerpt(std::string_view line) {
  constexpr std::size_t kLongest = 160;
  if (line.size() <= kLongest) return std::string(line);
  return std::string(line.substr(0, kLongest)) + "...";
}

template <class J>
std::int64_t integer_field(const J& message, const char* name, std::int64_t lowest, std::int64_t highest) {
  const auto found = message.find(name);
  if (found == message.end()) throw ProtocolError(std::string("/") + name + ": missing");
  const bool fits =
      found->is_number_integer() &&
      (found->is_number_unsigned()
           ? found->template get<std::uint64_t>() <= static_cast<std::uint64_t>(highest)
           : found->template get<std::int64_t>() >= lowest && found->template get<std::int64_t>() <= highest);
  if (!fits)
    throw ProtocolError(std::string("/") + name + ": must be an integer in [" + std::to_string(lowest) + ", " +
                        std::to_string(highest) + "] (got " + excerpt(found->dump()) + ")");
  return found->template get<std::int64_t>();
}

double wall_time_field(const Json& message) {
  const auto found = message.find("wall_time");
  if (found == message.end()) return 0.0;
  if (!found->is_number() || !std::isfinite(found->get<double>()) || found->get<double>() < 0.0)
    throw ProtocolError("/wall_time: must be a number of seconds >= 0 (got " + excerpt(found->dump()) + ")");
  return found->get<double>();
}

std::string data_file_field(const Json& message) {
  const auto found = message.find("data_file");
  if (found == message.end()) return {};
  if (!found->is_string()) throw ProtocolError("/data_file: must be a string (got " + excerpt(found->dump()) + ")");
  const std::string path = found->get<std::string>();
  // The job may run on another host with another working directory: only absolute paths mean
  // the same file to both sides.
  if (!path.empty() && !std::filesystem::path(path).is_absolute())
    throw ProtocolError("/data_file: must be an absolute path or empty (got \"" + excerpt(path) + "\")");
  return path;
}

constexpr std::int64_t kLowestCase = std::numeric_limits<std::int64_t>::min();
constexpr std::int64_t kHighestCase = std::numeric_limits<std::int64_t>::max();
constexpr std::int64_t kLargestAttempt = std::numeric_limits<int>::max();

template <class J>
std::string string_field(const J& message, const char* name) {
  const auto found = message.find(name);
  if (found == message.end()) throw ProtocolError(std::string("/") + name + ": missing");
  if (!found->is_string())
    throw ProtocolError(std::string("/") + name + ": must be a string (got " + excerpt(found->dump()) + ")");
  return found->template get<std::string>();
}

double seconds_field(const nlohmann::json& message) {
  const auto found = message.find("seconds");
  if (found == message.end()) throw ProtocolError("/seconds: missing");
  if (!found->is_number() || !std::isfinite(found->get<double>()) || found->get<double>() < 0.0)
    throw ProtocolError("/seconds: must be a number of seconds >= 0 (got " + excerpt(found->dump()) + ")");
  return found->get<double>();
}

int rank_field(const nlohmann::json& message) {
  return static_cast<int>(integer_field(message, "rank", 0, std::numeric_limits<int>::max()));
}

FailureKind failure_kind(const std::string& text) {
  for (const auto kind :
       {FailureKind::invalid, FailureKind::error, FailureKind::wall_time, FailureKind::storage, FailureKind::lost})
    if (to_string(kind) == text) return kind;
  throw ProtocolError("/kind: must be invalid, error, wall_time, storage or lost (got \"" + excerpt(text) + "\")");
}

JobReady ready_from_json(const nlohmann::json& message) {
  JobReady ready;
  ready.ranks = static_cast<int>(integer_field(message, "ranks", 1, std::numeric_limits<int>::max()));
  const auto hosts = message.find("hosts");
  if (hosts == message.end() || !hosts->is_array() || hosts->size() != static_cast<std::size_t>(ready.ranks))
    throw ProtocolError("/hosts: must be an array of one host name per rank");
  for (const auto& host : *hosts) {
    if (!host.is_string()) throw ProtocolError("/hosts: must hold strings (got " + excerpt(host.dump()) + ")");
    ready.hosts.push_back(host.get<std::string>());
  }
  ready.pid = integer_field(message, "pid", 0, kHighestCase);
  ready.version = string_field(message, "version");
  return ready;
}

RankLost rank_lost_from_json(const nlohmann::json& message) {
  RankLost lost;
  lost.rank = rank_field(message);
  lost.host = string_field(message, "host");
  lost.ranks = static_cast<int>(integer_field(message, "ranks", 1, std::numeric_limits<int>::max()));
  const auto silent = message.find("silent_seconds");
  if (silent == message.end() || !silent->is_number() || !std::isfinite(silent->get<double>()))
    throw ProtocolError("/silent_seconds: must be a number of seconds");
  lost.silent_seconds = silent->get<double>();
  return lost;
}

CaseStarted started_from_json(const nlohmann::json& message, std::int64_t case_id, int attempt) {
  return {case_id, attempt, rank_field(message), string_field(message, "host")};
}

CaseResult result_from_json(nlohmann::json&& message, std::int64_t case_id, int attempt) {
  CaseResult answer;
  answer.case_id = case_id;
  answer.attempt = attempt;
  answer.rank = rank_field(message);
  answer.seconds = seconds_field(message);
  const auto result = message.find("result");
  if (result == message.end() || !result->is_object()) throw ProtocolError("/result: missing or not an object");
  answer.data_file = string_field(message, "data_file");
  if (message.contains("data_file_size"))
    answer.data_file_size = integer_field(message, "data_file_size", 0, kHighestCase);
  if (message.contains("data_file_sha256")) answer.data_file_sha256 = string_field(message, "data_file_sha256");
  answer.result = std::move(*result);
  return answer;
}

CaseFailed failed_from_json(const nlohmann::json& message, std::int64_t case_id, int attempt) {
  return {case_id,
          attempt,
          rank_field(message),
          seconds_field(message),
          failure_kind(string_field(message, "kind")),
          string_field(message, "error")};
}

// The typed message of a JSON object from a job (decode_job_line).
JobMessage job_message_from_json(nlohmann::json&& message) {
  const auto type_field = message.find("type");
  if (type_field == message.end() || !type_field->is_string())
    return UnknownJobMessage{"/type: missing or not a string"};
  const std::string type = *type_field;
  try {
    if (type == "ready") return ready_from_json(message);
    if (type == "protocol_error") return JobProtocolError{string_field(message, "message")};
    if (type == "heartbeat") return JobHeartbeat{};
    if (type == "rank_lost") return rank_lost_from_json(message);
  } catch (const ProtocolError& error) {
    return UnknownJobMessage{"a '" + type + "' message: " + error.what()};
  }
  if (type != "started" && type != "result" && type != "failed")
    return UnknownJobMessage{"unknown message type '" + excerpt(type) + "'"};
  std::int64_t case_id = 0;
  int attempt = 0;
  try {
    case_id = integer_field(message, "case", kLowestCase, kHighestCase);
    attempt = static_cast<int>(integer_field(message, "attempt", 0, kLargestAttempt));
  } catch (const ProtocolError& error) {
    return UnknownJobMessage{"a '" + type + "' message: " + error.what()};
  }
  try {
    if (type == "started") return started_from_json(message, case_id, attempt);
    if (type == "result") return result_from_json(std::move(message), case_id, attempt);
    return failed_from_json(message, case_id, attempt);
  } catch (const ProtocolError& error) {
    return UnreadableAnswer{type, case_id, attempt, error.what()};
  }
}

}  // namespace

std::string to_string(FailureKind kind) {
  switch (kind) {
    case FailureKind::invalid:
      return "invalid";
    case FailureKind::error:
      return "error";
    case FailureKind::wall_time:
      return "wall_time";
    case FailureKind::storage:
      return "storage";
    case FailureKind::lost:
      return "lost";
  }
  return "error";
}

std::string serialize_message(const Json& message) {
  return message.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string protocol_line_from_serialized(std::string_view serialized_message) {
  std::string line;
  line.reserve(kProtocolPrefix.size() + serialized_message.size() + 1);
  line.append(kProtocolPrefix).append(serialized_message).push_back('\n');
  return line;
}

std::string protocol_line(const Json& message) { return protocol_line_from_serialized(serialize_message(message)); }

OrchestratorMessage decode_orchestrator_line(std::string_view line) {
  if (!line.starts_with(kProtocolPrefix))
    throw ProtocolError("not a protocol line (no \"" + std::string(kProtocolPrefix) + "\" prefix): " + excerpt(line));
  Json message;
  try {
    message = Json::parse(line.substr(kProtocolPrefix.size()));
  } catch (const nlohmann::json::parse_error& e) {
    throw ProtocolError("not JSON: " + std::string(e.what()) + ": " + excerpt(line));
  }
  if (!message.is_object()) throw ProtocolError("a message must be a JSON object: " + excerpt(line));
  const auto type = message.find("type");
  if (type == message.end() || !type->is_string())
    throw ProtocolError("/type: missing or not a string: " + excerpt(line));
  if (*type == "stop") return StopRequest{};
  if (*type != "case") throw ProtocolError("/type: unknown message type " + excerpt(type->dump()));

  // Without its case and attempt a case message cannot be answered as that case.
  const std::int64_t case_id = integer_field(message, "case", kLowestCase, kHighestCase);
  const auto attempt = static_cast<int>(integer_field(message, "attempt", 0, kLargestAttempt));
  try {
    return assignment_from_json(message);
  } catch (const ProtocolError& e) {
    return MalformedAssignment{case_id, attempt, "case message: " + std::string(e.what())};
  }
}

Json to_json(const CaseAssignment& a) {
  return Json{{"type", "case"},         {"case", a.case_id},        {"attempt", a.attempt},
              {"document", a.document}, {"wall_time", a.wall_time}, {"data_file", a.data_file}};
}

CaseAssignment assignment_from_json(const Json& message) {
  CaseAssignment a;
  a.case_id = integer_field(message, "case", kLowestCase, kHighestCase);
  a.attempt = static_cast<int>(integer_field(message, "attempt", 0, kLargestAttempt));
  const auto document = message.find("document");
  if (document == message.end()) throw ProtocolError("/document: missing");
  a.document = *document;
  a.wall_time = wall_time_field(message);
  a.data_file = data_file_field(message);
  return a;
}

Json ready_message(int ranks, const std::vector<std::string>& hosts, std::int64_t pid, std::string_view version) {
  return Json{{"type", "ready"}, {"ranks", ranks}, {"hosts", hosts}, {"pid", pid}, {"version", std::string(version)}};
}

Json started_message(std::int64_t case_id, int attempt, int rank, const std::string& host) {
  return Json{{"type", "started"}, {"case", case_id}, {"attempt", attempt}, {"rank", rank}, {"host", host}};
}

Json result_message(std::int64_t case_id, int attempt, int rank, double seconds, Json result,
                    const std::string& data_file, std::uintmax_t data_file_size, const std::string& data_file_sha256) {
  Json message{{"type", "result"},      {"case", case_id},    {"attempt", attempt},
               {"rank", rank},          {"seconds", seconds}, {"result", std::move(result)},
               {"data_file", data_file}};
  if (!data_file.empty()) {
    message["data_file_size"] = data_file_size;
    message["data_file_sha256"] = data_file_sha256;
  }
  return message;
}

Json failed_message(std::int64_t case_id, int attempt, int rank, double seconds, FailureKind kind,
                    const std::string& error) {
  return Json{{"type", "failed"},   {"case", case_id},         {"attempt", attempt}, {"rank", rank},
              {"seconds", seconds}, {"kind", to_string(kind)}, {"error", error}};
}

Json protocol_error_message(const std::string& message) {
  return Json{{"type", "protocol_error"}, {"message", message}};
}

Json heartbeat_message() { return Json{{"type", "heartbeat"}}; }

Json rank_lost_message(int rank, const std::string& host, int ranks_left, double silent_seconds) {
  return Json{
      {"type", "rank_lost"}, {"rank", rank}, {"host", host}, {"ranks", ranks_left}, {"silent_seconds", silent_seconds}};
}

Json to_json(const StopRequest&) { return Json{{"type", "stop"}}; }

std::optional<JobMessage> decode_job_line(std::string_view line) {
  if (line.substr(0, kProtocolPrefix.size()) != kProtocolPrefix) return std::nullopt;
  auto message = nlohmann::json::parse(line.substr(kProtocolPrefix.size()), nullptr, false);
  if (message.is_discarded() || !message.is_object()) return std::nullopt;
  return job_message_from_json(std::move(message));
}

}  // namespace aerobreak
