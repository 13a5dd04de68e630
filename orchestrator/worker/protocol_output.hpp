#pragma once
#include <nlohmann/json.hpp>
#include <string_view>

namespace aerobreak {

// Rank 0's channel to the orchestrator: the job's original stdout, kept for protocol lines alone.
// File descriptor 1 is pointed at stderr, so that anything else printed to stdout (by a library,
// say) goes to the log instead of splitting a protocol line. Each line goes out in whole writes
// at once, unbuffered: the orchestrator sees a message as soon as it is sent.
class ProtocolOutput {
 public:
  ProtocolOutput();
  ProtocolOutput(const ProtocolOutput&) = delete;
  ProtocolOutput& operator=(const ProtocolOutput&) = delete;
  ~ProtocolOutput();

  void send(const nlohmann::ordered_json& message);
  // A message already serialized as a compact JSON object (as the ranks send their answers).
  void send_serialized(std::string_view message);

 private:
  void write_line(std::string_view line);
  int fd_ = -1;
};

// For ranks other than 0: their stdout carries no protocol, so it joins stderr.
void send_stdout_to_stderr();

}  // namespace aerobreak
