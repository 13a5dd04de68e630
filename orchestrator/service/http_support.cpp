#include "orchestrator/service/http_support.hpp"

#include <charconv>
#include <memory>
#include <stdexcept>

#include "engine/impact/outcome.hpp"
#include "orchestrator/app/compression.hpp"

namespace aerobreak {
namespace {

// Answers shorter than this go out uncompressed: compressing them saves less than it costs.
constexpr std::size_t kCompressFromBytes = 1024;

// The content types cpp-httplib would compress (text, JSON, JavaScript, XML, SVG).
bool compressible(const std::string& content_type) {
  if (content_type.rfind("text/", 0) == 0) return content_type.rfind("text/event-stream", 0) != 0;
  for (const char* kind : {"json", "javascript", "xml", "svg"})
    if (content_type.find(kind) != std::string::npos) return true;
  return false;
}

}  // namespace

bool accepts_gzip(const httplib::Request& request) {
  return request.get_header_value("Accept-Encoding").find("gzip") != std::string::npos;
}

void compress_answer(const httplib::Request& request, httplib::Response& response) {
  // Error answers keep their body, where the service's error handler looks for it (error_answers.cpp).
  if (response.status >= 400 || response.body.empty() || response.has_header("Content-Encoding")) return;
  const std::string content_type = response.get_header_value("Content-Type");
  if (!compressible(content_type)) return;
  // A Range counts the bytes of the answer as it is (byte_ranges.hpp): one asked for is not gzipped.
  const bool gzipped =
      response.body.size() >= kCompressFromBytes && accepts_gzip(request) && !request.has_header("Range");
  auto body = std::make_shared<const std::string>(gzipped ? gzip(response.body) : std::move(response.body));
  response.body.clear();
  response.headers.erase("Content-Type");
  response.set_header("Vary", "Accept-Encoding");
  if (gzipped) response.set_header("Content-Encoding", "gzip");
  response.set_content_provider(body->size(), content_type.c_str(),
                                [body](std::size_t offset, std::size_t length, httplib::DataSink& sink) {
                                  return sink.write(body->data() + offset, length);
                                });
}

void send_json(httplib::Response& response, int status, const nlohmann::ordered_json& body) {
  response.status = status;
  // Text a client sent (a path, a parameter, a key) can be invalid UTF-8, with which dump() would
  // throw where nothing catches it: such bytes are written as U+FFFD instead.
  response.set_content(body.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace), "application/json");
}

void send_error(httplib::Response& response, const RequestError& error) {
  send_json(response, error.status, {{"error", error.message}, {"violations", error.violations}});
}

nlohmann::ordered_json violations_json(const std::vector<SchemaViolation>& violations) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const auto& violation : violations)
    list.push_back({{"pointer", violation.pointer}, {"message", violation.message}});
  return list;
}

std::optional<std::string> single_parameter(const httplib::Request& request, const std::string& name) {
  const std::size_t given = request.get_param_value_count(name);
  if (given == 0) return std::nullopt;
  if (given > 1) {
    const std::string message =
        "query parameter '" + name + "' is given " + std::to_string(given) + " times; it takes one value";
    throw RequestError{400, message, nlohmann::ordered_json::array({{{"parameter", name}, {"message", message}}})};
  }
  return request.get_param_value(name);
}

bool flag_parameter(const httplib::Request& request, const std::string& name) {
  const auto text = single_parameter(request, name);
  if (!text || *text == "false") return false;
  if (*text != "true")
    throw RequestError{400, "query parameter '" + name + "' must be true or false (got '" + *text + "')"};
  return true;
}

std::optional<CaseStatus> status_parameter(const httplib::Request& request) {
  const auto text = single_parameter(request, "status");
  if (!text) return std::nullopt;
  const auto status = parse_case_status(*text);
  if (!status) throw RequestError{400, "query parameter 'status' must be queued, running, done, failed or cancelled"};
  return status;
}

std::optional<std::string> outcome_parameter(const httplib::Request& request) {
  auto outcome = single_parameter(request, "outcome");
  if (outcome && !parse_outcome(*outcome))
    throw RequestError{400, "query parameter 'outcome' must be " + outcome_names_text()};
  return outcome;
}

std::size_t unsigned_parameter(const httplib::Request& request, const std::string& name, std::size_t fallback,
                               std::size_t maximum) {
  const auto given = single_parameter(request, name);
  if (!given) return fallback;
  const std::string& text = *given;
  std::size_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || value > maximum)
    throw RequestError{400, "query parameter '" + name + "' must be an integer from 0 to " + std::to_string(maximum) +
                                " (got '" + text + "')"};
  return value;
}

PageRequest page_request(const httplib::Request& request, const ServiceOptions& options) {
  PageRequest page;
  page.limit = unsigned_parameter(request, "limit", 100, options.max_page_size);
  page.offset = unsigned_parameter(request, "offset", 0, std::size_t{1} << 40);
  return page;
}

std::int64_t path_id(const httplib::Request& request) {
  std::int64_t id = 0;
  const std::string text = request.matches[1];
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), id);
  if (error != std::errc() || end != text.data() + text.size()) throw RequestError{404, "no such id: " + text};
  return id;
}

StudyRecord existing_study(Store& store, std::int64_t id) {
  auto study = store.study(id);
  if (!study) throw RequestError{404, "no study " + std::to_string(id)};
  return *study;
}

bool names_current_tag(const httplib::Request& request, const std::string& etag) {
  const std::string header = request.get_header_value("If-None-Match");
  std::size_t start = 0;
  while (start < header.size()) {
    std::size_t end = header.find(',', start);
    if (end == std::string::npos) end = header.size();
    std::string tag = header.substr(start, end - start);
    tag.erase(0, tag.find_first_not_of(" \t"));
    tag.erase(tag.find_last_not_of(" \t") + 1);
    if (tag.rfind("W/", 0) == 0) tag.erase(0, 2);
    if (tag == "*" || tag == etag) return true;
    start = end + 1;
  }
  return false;
}

void send_kept_json(const httplib::Request& request, httplib::Response& response, const std::string& etag,
                    std::shared_ptr<const void> owner, const std::string& body, const std::string& content_encoding) {
  send_kept(request, response, etag, std::move(owner), body, "application/json", content_encoding);
}

void send_kept(const httplib::Request& request, httplib::Response& response, const std::string& etag,
               std::shared_ptr<const void> owner, const std::string& body, const std::string& content_type,
               const std::string& content_encoding) {
  response.set_header("ETag", etag);
  response.set_header("Cache-Control", "no-cache");
  if (names_current_tag(request, etag)) {
    response.status = 304;
    return;
  }
  response.status = 200;
  if (!content_encoding.empty()) response.set_header("Content-Encoding", content_encoding);
  response.set_content_provider(
      body.size(), content_type.c_str(),
      [owner = std::move(owner), &body](std::size_t offset, std::size_t length, httplib::DataSink& sink) {
        return sink.write(body.data() + offset, length);
      });
}

}  // namespace aerobreak
