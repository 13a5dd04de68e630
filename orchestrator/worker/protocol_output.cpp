#include "orchestrator/worker/protocol_output.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

#include "orchestrator/worker/worker_protocol.hpp"

namespace aerobreak {

ProtocolOutput::ProtocolOutput() {
  std::fflush(stdout);
  fd_ = ::dup(STDOUT_FILENO);
  if (fd_ < 0) throw std::runtime_error(std::string("cannot keep stdout for the protocol: ") + std::strerror(errno));
  send_stdout_to_stderr();
}

ProtocolOutput::~ProtocolOutput() {
  if (fd_ >= 0) ::close(fd_);
}

void ProtocolOutput::send(const nlohmann::ordered_json& message) { write_line(protocol_line(message)); }

void ProtocolOutput::send_serialized(std::string_view message) { write_line(protocol_line_from_serialized(message)); }

void ProtocolOutput::write_line(std::string_view line) {
  while (!line.empty()) {
    const ssize_t written = ::write(fd_, line.data(), line.size());
    if (written < 0 && errno == EINTR) continue;
    if (written < 0) throw std::runtime_error(std::string("cannot write to the orchestrator: ") + std::strerror(errno));
    line.remove_prefix(static_cast<std::size_t>(written));
  }
}

void send_stdout_to_stderr() {
  std::fflush(stdout);
  if (::dup2(STDERR_FILENO, STDOUT_FILENO) < 0)
    throw std::runtime_error(std::string("cannot send stdout to stderr: ") + std::strerror(errno));
}

}  // namespace aerobreak
