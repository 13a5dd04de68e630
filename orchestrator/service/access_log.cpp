#include "orchestrator/service/access_log.hpp"

#include <chrono>
#include <cstdio>

#include "orchestrator/service/bounded_server.hpp"

namespace aerobreak {
namespace {

constexpr std::size_t kMaxTargetLength = 200;

std::string printable(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (out.size() >= kMaxTargetLength) return out + "...";
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte >= 0x7f || c == '"' || c == '\\') {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02X", byte);
      out += escaped;
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace

httplib::Logger access_logger(std::function<void(const std::string&)> log) {
  return [log = std::move(log)](const httplib::Request& request, const httplib::Response& response) {
    const auto started = current_request_started();
    const double milliseconds =
        started ? std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - *started).count() : 0.0;
    char time_text[32];
    std::snprintf(time_text, sizeof time_text, "%.1f ms", milliseconds);
    const std::string client =
        request.remote_addr.empty() ? "-" : request.remote_addr + ":" + std::to_string(request.remote_port);
    const std::string method = request.method.empty() ? "-" : printable(request.method);
    const std::string target = request.target.empty() ? "-" : printable(request.target);
    log(client + " \"" + method + " " + target + "\" " + std::to_string(response.status) + " " + time_text);
  };
}

}  // namespace aerobreak
