#include "orchestrator/service/request_checks.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <optional>
#include <string>

#include "orchestrator/service/bounded_server.hpp"
#include "orchestrator/service/http_support.hpp"

namespace aerobreak {
namespace {

bool has_body(const std::string& method) {
  return method == "POST" || method == "PUT" || method == "PATCH" || method == "DELETE";
}

std::string lowercase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

std::string trimmed(const std::string& text) {
  const auto begin = text.find_first_not_of(" \t");
  if (begin == std::string::npos) return {};
  return text.substr(begin, text.find_last_not_of(" \t") - begin + 1);
}

// Compares without an early exit, so that response times do not reveal how much of a guess was right.
bool same_token(const std::string& given, const std::string& expected) {
  unsigned char difference = given.size() == expected.size() ? 0 : 1;
  for (std::size_t i = 0; i < given.size(); ++i)
    difference |= static_cast<unsigned char>(given[i] ^ expected[i % std::max<std::size_t>(expected.size(), 1)]);
  return difference == 0;
}

// The request's body length: every Content-Length value (repeated headers, or a comma list) must
// be the same decimal number (RFC 9112 6.3: differing lengths make the framing invalid).
std::optional<std::size_t> content_length(const httplib::Request& request) {
  std::optional<std::size_t> length;
  const std::size_t headers = request.get_header_value_count("Content-Length");
  for (std::size_t h = 0; h < headers; ++h) {
    const std::string values = request.get_header_value("Content-Length", h);
    for (std::size_t begin = 0; begin <= values.size();) {
      const std::size_t end = std::min(values.find(',', begin), values.size());
      const std::string value = trimmed(values.substr(begin, end - begin));
      std::size_t parsed = 0;
      const auto [stop, error] = std::from_chars(value.data(), value.data() + value.size(), parsed);
      if (value.empty() || error != std::errc() || stop != value.data() + value.size())
        throw RequestError{400, "Content-Length must be a decimal number of bytes"};
      if (length && *length != parsed) throw RequestError{400, "the request has conflicting Content-Length values"};
      length = parsed;
      begin = end + 1;
    }
  }
  return length;
}

// A connection on a slot kept for /api/health (ConnectionSlots) may ask for nothing else.
void check_health_only(const httplib::Request& request, const ServiceOptions& options) {
  if (!current_connection_health_only()) return;
  if ((request.method == "GET" || request.method == "HEAD") && request.path == "/api/health") return;
  throw RequestError{503, "the service is serving its limit of " + std::to_string(options.connections.max_connections) +
                              " connections; beyond it only GET /api/health is answered: try again shortly"};
}

void check_framing(const httplib::Request& request, const ServiceOptions& options) {
  if (request.has_header("Transfer-Encoding"))
    throw RequestError{411, "a request body needs a Content-Length (Transfer-Encoding is not accepted)"};
  const auto length = content_length(request);
  if (!has_body(request.method)) return;
  if (!length) throw RequestError{411, "a " + request.method + " request needs a Content-Length (0 for no body)"};
  if (*length > options.max_body_bytes)
    throw RequestError{413, "the request body (" + std::to_string(*length) + " bytes) is larger than the " +
                                std::to_string(options.max_body_bytes) + " bytes the service accepts"};
}

void check_origin(const httplib::Request& request) {
  if (!request.has_header("Host"))
    throw RequestError{403, "the request has no Host header; without a token the service answers loopback names only"};
  const std::string host = host_of(request.get_header_value("Host"));
  if (!is_loopback_host(host))
    throw RequestError{403, "Host '" + host +
                                "' is not a loopback name: without a token the service answers only requests "
                                "addressed to 127.0.0.1, ::1 or localhost"};
}

void check_token(const httplib::Request& request, httplib::Response& response, const std::string& token) {
  const std::string header = request.get_header_value("Authorization");
  const std::string prefix = "Bearer ";
  if (header.rfind(prefix, 0) == 0 && same_token(header.substr(prefix.size()), token)) return;
  response.set_header("WWW-Authenticate", "Bearer");
  throw RequestError{401, "this endpoint needs 'Authorization: Bearer TOKEN'"};
}

void check_media_type(const httplib::Request& request) {
  const std::string content_type = request.get_header_value("Content-Type");
  if (lowercase(trimmed(content_type.substr(0, content_type.find(';')))) != "application/json")
    throw RequestError{415, "a POST needs 'Content-Type: application/json' (got '" + content_type + "')"};
}

}  // namespace

std::string host_of(const std::string& host_header) {
  const std::string value = trimmed(host_header);
  if (!value.empty() && value.front() == '[') return value.substr(1, value.find(']') - 1);
  const auto colon = value.find(':');
  return colon != std::string::npos && value.find(':', colon + 1) == std::string::npos ? value.substr(0, colon) : value;
}

httplib::Server::HandlerResponse check_request(const httplib::Request& request, httplib::Response& response,
                                               const ServiceOptions& options) {
  try {
    check_health_only(request, options);
    check_framing(request, options);
    if (!options.token) check_origin(request);
    const bool reads_only = request.method == "GET" || request.method == "HEAD";
    if (options.token && !reads_only) check_token(request, response, *options.token);
    if (!options.token && request.method == "POST") check_media_type(request);
  } catch (const RequestError& error) {
    send_error(response, error);
    close_connection_after_response(response);
    return httplib::Server::HandlerResponse::Handled;
  }
  return httplib::Server::HandlerResponse::Unhandled;
}

}  // namespace aerobreak
