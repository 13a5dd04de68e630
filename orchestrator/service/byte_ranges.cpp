#include "orchestrator/service/byte_ranges.hpp"

#include <algorithm>
#include <charconv>
#include <limits>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace aerobreak {
namespace {

constexpr std::uint64_t kUnbounded = std::numeric_limits<std::uint64_t>::max();

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
  return text;
}

// Digits as a number; one too large for 64 bits reads as the largest (beyond any answer).
std::optional<std::uint64_t> number(std::string_view digits) {
  if (digits.empty() || digits.find_first_not_of("0123456789") != std::string_view::npos) return std::nullopt;
  std::uint64_t value = 0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  return error == std::errc::result_out_of_range ? kUnbounded : value;
}

// One range-spec ("first-last", "first-", "-suffix") resolved against `length`: nullopt when it is
// not satisfiable, `malformed` set when it is not a range-spec.
std::optional<ByteRange> resolve(std::string_view spec, std::uint64_t length, bool& malformed) {
  const auto dash = spec.find('-');
  if (dash == std::string_view::npos) return malformed = true, std::nullopt;
  const std::string_view head = spec.substr(0, dash), tail = spec.substr(dash + 1);
  if (head.empty()) {  // the last `suffix` bytes
    const auto suffix = number(tail);
    if (!suffix) return malformed = true, std::nullopt;
    if (*suffix == 0 || length == 0) return std::nullopt;
    return ByteRange{length - std::min(*suffix, length), length - 1};
  }
  const auto first = number(head);
  const auto last = tail.empty() ? std::optional(kUnbounded) : number(tail);
  if (!first || !last || *last < *first) return malformed = true, std::nullopt;
  if (*first >= length) return std::nullopt;
  return ByteRange{*first, std::min(*last, length - 1)};
}

std::vector<ByteRange> merged(std::vector<ByteRange> parts) {
  std::sort(parts.begin(), parts.end(), [](const ByteRange& a, const ByteRange& b) { return a.first < b.first; });
  std::vector<ByteRange> out;
  for (const auto& part : parts) {
    if (!out.empty() && part.first <= out.back().last + 1)
      out.back().last = std::max(out.back().last, part.last);
    else
      out.push_back(part);
  }
  return out;
}

std::string content_range(const ByteRange& part, std::uint64_t length) {
  return "bytes " + std::to_string(part.first) + "-" + std::to_string(part.last) + "/" + std::to_string(length);
}

void replace_header(httplib::Response& response, const std::string& name, const std::string& value) {
  response.headers.erase(name);
  response.headers.emplace(name, value);
}

void answer_unsatisfiable(httplib::Response& response, std::uint64_t length) {
  response.content_provider_ = nullptr;
  response.content_length_ = 0;
  response.headers.erase("Content-Encoding");
  response.headers.erase("ETag");
  response.status = 416;
  response.body = nlohmann::json{{"error", "the range asked for lies beyond the " + std::to_string(length) +
                                               " bytes of this answer"},
                                 {"violations", nlohmann::json::array()}}
                      .dump();
  replace_header(response, "Content-Type", "application/json");
  replace_header(response, "Content-Range", "bytes */" + std::to_string(length));
  replace_header(response, "Content-Length", std::to_string(response.body.size()));
}

// One part of an answer held in memory or streamed by a provider of known length.
void answer_part(httplib::Response& response, const ByteRange& part, std::uint64_t length) {
  const auto count = static_cast<std::size_t>(part.last - part.first + 1);
  if (response.content_provider_) {
    response.content_provider_ = [provider = std::move(response.content_provider_), offset = part.first](
                                     std::size_t at, std::size_t size, httplib::DataSink& sink) {
      return provider(static_cast<std::size_t>(offset) + at, size, sink);
    };
    response.content_length_ = count;
  } else {
    response.body = response.body.substr(static_cast<std::size_t>(part.first), count);
  }
  response.status = 206;
  replace_header(response, "Content-Range", content_range(part, length));
  replace_header(response, "Content-Length", std::to_string(count));
}

// Several parts of an answer held in memory, as multipart/byteranges (RFC 9110 14.6).
void answer_parts(httplib::Response& response, const std::vector<ByteRange>& parts, std::uint64_t length) {
  // A delimiter must not occur in the parts (RFC 2046 5.1.1).
  std::string boundary = "aerobreak-byteranges-" + std::to_string(length);
  while (response.body.find(boundary) != std::string::npos) boundary += "-";
  const std::string type = response.get_header_value("Content-Type");
  std::string body;
  for (const auto& part : parts) {
    body += "--" + boundary + "\r\nContent-Type: " + type + "\r\nContent-Range: " + content_range(part, length) +
            "\r\n\r\n";
    body.append(response.body, static_cast<std::size_t>(part.first),
                static_cast<std::size_t>(part.last - part.first + 1));
    body += "\r\n";
  }
  body += "--" + boundary + "--\r\n";
  response.body = std::move(body);
  response.status = 206;
  replace_header(response, "Content-Type", "multipart/byteranges; boundary=" + boundary);
  replace_header(response, "Content-Length", std::to_string(response.body.size()));
}

// The whole of an answer streamed by a provider of known length, at most kMaxGatheredBytes, as
// one string; nullopt for a longer one or a provider that fails or stops short.
std::optional<std::string> gathered(const httplib::Response& response) {
  const std::size_t length = response.content_length_;
  if (length > kMaxGatheredBytes) return std::nullopt;
  std::string body;
  body.reserve(length);
  httplib::DataSink sink;
  sink.write = [&body, length](const char* data, std::size_t size) {
    body.append(data, std::min(size, length - body.size()));
    return true;
  };
  sink.is_writable = [] { return true; };
  while (body.size() < length) {
    const std::size_t before = body.size();
    if (!response.content_provider_(before, length - before, sink) || body.size() == before) return std::nullopt;
  }
  return body;
}

}  // namespace

RangePlan plan_byte_ranges(std::string_view header, std::uint64_t length) {
  header = trimmed(header);
  if (!header.starts_with("bytes=")) return {};
  header.remove_prefix(6);
  std::vector<ByteRange> satisfiable;
  bool malformed = false;
  while (!malformed) {
    const auto comma = std::min(header.find(','), header.size());
    if (const auto part = resolve(trimmed(header.substr(0, comma)), length, malformed)) satisfiable.push_back(*part);
    if (comma == header.size()) break;
    header.remove_prefix(comma + 1);
  }
  if (malformed) return {};
  if (satisfiable.empty()) return {RangePlan::Kind::unsatisfiable, {}};
  auto parts = merged(std::move(satisfiable));
  if (parts.size() > kMaxRangeParts) return {};
  return {RangePlan::Kind::partial, std::move(parts)};
}

void apply_byte_ranges(const httplib::Request& request, httplib::Response& response) {
  if (request.method != "GET" || response.status != 200 || !request.has_header("Range")) return;
  if (response.is_chunked_content_provider_ || (response.content_provider_ && response.content_length_ == 0)) return;
  if (request.has_header("If-Range") && request.get_header_value("If-Range") != response.get_header_value("ETag"))
    return;
  const std::uint64_t length = response.content_provider_ ? response.content_length_ : response.body.size();
  const RangePlan plan = plan_byte_ranges(request.get_header_value("Range"), length);
  if (plan.kind == RangePlan::Kind::unsatisfiable) return answer_unsatisfiable(response, length);
  if (plan.kind == RangePlan::Kind::whole) return;
  if (plan.parts.size() == 1) return answer_part(response, plan.parts.front(), length);
  if (response.content_provider_) {
    auto body = gathered(response);
    if (!body) return;  // the whole answer
    response.content_provider_ = nullptr;
    response.content_length_ = 0;
    response.body = std::move(*body);
  }
  answer_parts(response, plan.parts, length);
}

}  // namespace aerobreak
