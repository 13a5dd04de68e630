#pragma once
// The line protocol between the orchestrator and a worker job (docs/WORKER_PROTOCOL.md): its one
// place of encoding and decoding.
//
// Every message is one line: the prefix "@aerobreak " followed by a compact JSON object and '\n'.
// Lines without the prefix are not protocol (the orchestrator logs them).
//
// Orchestrator -> job (stdin of rank 0):
//   {"type":"case","case":ID,"attempt":A,"document":{case},"wall_time":S,"data_file":"PATH"}
//       wall_time in seconds, 0 = no limit (optional, default 0); data_file the absolute path of
//       the HDF5 bulk file, "" for none (optional, default "").
//   {"type":"stop"}   finish the cases in flight, send their results, exit 0.
//   EOF without stop: the orchestrator is gone; the job aborts at once.
// Job -> orchestrator (stdout of rank 0):
//   {"type":"ready","ranks":K,"hosts":[...],"pid":P,"version":"V"}          once, first
//   {"type":"started","case":ID,"attempt":A,"rank":R,"host":"H"}
//   {"type":"result","case":ID,"attempt":A,"rank":R,"seconds":S,"result":{...},"data_file":"PATH",
//    "data_file_size":BYTES,"data_file_sha256":"HEX"}      (the last two only with a data file)
//   {"type":"failed","case":ID,"attempt":A,"rank":R,"seconds":S,"kind":"invalid|error|wall_time|storage|lost",
//    "error":"..."}
//   {"type":"protocol_error","message":"..."}                                a line that is no message
//   {"type":"heartbeat"}                                     every kHeartbeatInterval while the job runs
//   {"type":"rank_lost","rank":R,"host":"H","ranks":K,"silent_seconds":S}   a busy rank silent past the
//       silence limit: it gets no more cases, K ranks are left; its case is answered "failed", kind "lost"
// Every case assignment is answered by exactly one result or failed message.
#include <chrono>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace aerobreak {

inline constexpr std::string_view kProtocolPrefix = "@aerobreak ";

// How often a running job says it is alive: rank 0 to the orchestrator ("heartbeat"), and each
// busy rank to rank 0, so that a job or rank that has gone silent can be told from a long case.
inline constexpr std::chrono::seconds kHeartbeatInterval{2};
// Silent this long, a job (for the orchestrator) or a busy rank (for rank 0) is taken for lost: its
// node is gone or cut off, or its process stopped. The default of --silence-limit.
inline constexpr std::chrono::seconds kDefaultSilenceLimit{60};

// One case handed to the job.
struct CaseAssignment {
  std::int64_t case_id = 0;
  int attempt = 0;
  nlohmann::ordered_json document;  // schemas/case.schema.json; judged by the case runner, not here
  double wall_time = 0.0;           // seconds; 0: no limit
  std::string data_file;            // absolute path of the HDF5 bulk file; empty: none
};

// A case message whose case and attempt could be read but whose other fields are wrong: it is
// answered with a "failed" message of kind "invalid", so that no case is left without an answer.
struct MalformedAssignment {
  std::int64_t case_id = 0;
  int attempt = 0;
  std::string error;
};

struct StopRequest {};

using OrchestratorMessage = std::variant<CaseAssignment, MalformedAssignment, StopRequest>;

// A line from the orchestrator that cannot be tied to any case: answered by "protocol_error".
class ProtocolError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// storage: the case's data file could not be written (disk full, no permission, I/O error): a
// fault of the machine, not of the case. lost: the rank running it went silent (rank_lost).
enum class FailureKind { invalid, error, wall_time, storage, lost };
std::string to_string(FailureKind kind);

// The line for one message: prefix, compact JSON, '\n'. Invalid UTF-8 in strings (an error text
// quoting a file name, say) is replaced rather than making the message unsendable.
std::string protocol_line(const nlohmann::ordered_json& message);
// The same for a message already serialized as a compact JSON object.
std::string protocol_line_from_serialized(std::string_view serialized_message);
// Compact JSON of a message, as it travels between ranks.
std::string serialize_message(const nlohmann::ordered_json& message);

// Decodes one line from the orchestrator (without its '\n'). Throws ProtocolError.
OrchestratorMessage decode_orchestrator_line(std::string_view line);

// A case assignment as the JSON object of its "case" message, and back (throws ProtocolError).
nlohmann::ordered_json to_json(const CaseAssignment& assignment);
CaseAssignment assignment_from_json(const nlohmann::ordered_json& message);

nlohmann::ordered_json ready_message(int ranks, const std::vector<std::string>& hosts, std::int64_t pid,
                                     std::string_view version);
nlohmann::ordered_json started_message(std::int64_t case_id, int attempt, int rank, const std::string& host);
// With a data file, its size in bytes and SHA-256 travel with it.
nlohmann::ordered_json result_message(std::int64_t case_id, int attempt, int rank, double seconds,
                                      nlohmann::ordered_json result, const std::string& data_file,
                                      std::uintmax_t data_file_size = 0, const std::string& data_file_sha256 = {});
nlohmann::ordered_json failed_message(std::int64_t case_id, int attempt, int rank, double seconds, FailureKind kind,
                                      const std::string& error);
nlohmann::ordered_json protocol_error_message(const std::string& message);
nlohmann::ordered_json heartbeat_message();
nlohmann::ordered_json rank_lost_message(int rank, const std::string& host, int ranks_left, double silent_seconds);
nlohmann::ordered_json to_json(const StopRequest& stop);

// Job -> orchestrator, as the orchestrator reads them: one type per message, decoded in one place
// (decode_job_line). Each field is checked when the line is read; a message whose case and attempt
// can be read but whose other fields cannot becomes an UnreadableAnswer, so that no case is left
// without an answer.
struct JobReady {
  int ranks = 0;
  std::vector<std::string> hosts;  // of each rank, in rank order
  std::int64_t pid = 0;
  std::string version;
};

struct CaseStarted {
  std::int64_t case_id = 0;
  int attempt = 0;
  int rank = 0;
  std::string host;
};

struct CaseResult {
  std::int64_t case_id = 0;
  int attempt = 0;
  int rank = 0;
  double seconds = 0.0;
  nlohmann::json result;             // schemas/result.schema.json
  std::string data_file;             // the HDF5 bulk file written; empty: none
  std::int64_t data_file_size = -1;  // bytes; -1: not given (no data file)
  std::string data_file_sha256;      // empty: not given
};

struct CaseFailed {
  std::int64_t case_id = 0;
  int attempt = 0;
  int rank = 0;
  double seconds = 0.0;
  FailureKind kind = FailureKind::error;
  std::string error;
};

// A "result", "failed" or "started" message for a case and attempt whose other fields are wrong.
struct UnreadableAnswer {
  std::string type;
  std::int64_t case_id = 0;
  int attempt = 0;
  std::string problem;
};

struct JobProtocolError {
  std::string message;
};

struct JobHeartbeat {};

// Rank 0 gave up a busy rank that went silent; `ranks` are left (its case comes as CaseFailed,
// kind lost).
struct RankLost {
  int rank = 0;
  std::string host;
  int ranks = 0;
  double silent_seconds = 0.0;
};

// A protocol line that is none of the above (an unknown type, a ready message with wrong fields, a
// case message without its case or attempt): the orchestrator logs it.
struct UnknownJobMessage {
  std::string problem;
};

using JobMessage = std::variant<JobReady, CaseStarted, CaseResult, CaseFailed, UnreadableAnswer, JobProtocolError,
                                JobHeartbeat, RankLost, UnknownJobMessage>;

// Decodes one line from a worker job (without its '\n'), for the orchestrator: the message when
// the line carries the prefix and a JSON object after it; nullopt for any other line (output
// that is not protocol, which the orchestrator logs).
std::optional<JobMessage> decode_job_line(std::string_view line);

}  // namespace aerobreak
