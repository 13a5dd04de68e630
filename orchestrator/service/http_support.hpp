#pragma once
#include <httplib.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "orchestrator/service/service.hpp"
#include "orchestrator/store/store.hpp"
#include "orchestrator/study/study.hpp"

// What every group of endpoints shares: the JSON error answer, query and path parameters, and the
// wrapper that turns a RequestError into its answer. Each group of endpoints lives in a file of its
// own; routes.cpp lists them all.
namespace aerobreak {

// A request that cannot be served as asked: its status and the JSON body that says why.
struct RequestError {
  int status;
  std::string message;
  nlohmann::ordered_json violations = nlohmann::ordered_json::array();
};

void send_json(httplib::Response& response, int status, const nlohmann::ordered_json& body);
void send_error(httplib::Response& response, const RequestError& error);
nlohmann::ordered_json violations_json(const std::vector<SchemaViolation>& violations);

// Every query parameter that takes one value is read here. Query parameter `name`: its value,
// nullopt when absent; RequestError 400 naming it when it is given more than once (a second value
// is refused, never silently dropped). Only axis.NAME filters (grid_filter.hpp) take several.
std::optional<std::string> single_parameter(const httplib::Request& request, const std::string& name);
// ?NAME=true or ?NAME=false (absent: false); RequestError 400 otherwise.
bool flag_parameter(const httplib::Request& request, const std::string& name);
// ?status= as a case status (queued, running, done, failed, cancelled); RequestError 400 otherwise.
std::optional<CaseStatus> status_parameter(const httplib::Request& request);
// ?outcome= as an outcome class (stick, bounce, break-up, undetermined); RequestError 400 otherwise.
std::optional<std::string> outcome_parameter(const httplib::Request& request);
// Query parameter `name` as an integer in [0, maximum], `fallback` when absent; RequestError 400
// naming the parameter otherwise.
std::size_t unsigned_parameter(const httplib::Request& request, const std::string& name, std::size_t fallback,
                               std::size_t maximum);
PageRequest page_request(const httplib::Request& request, const ServiceOptions& options);
// The id captured by the route's first group; RequestError 404 when it is not an integer.
std::int64_t path_id(const httplib::Request& request);
// The study `id`; RequestError 404 when there is none.
StudyRecord existing_study(Store& store, std::int64_t id);

// Whether the request's If-None-Match (RFC 9110, 13.1.2: a list of tags or "*", compared weakly)
// names `etag`: then the answer is 304 without a body.
bool names_current_tag(const httplib::Request& request, const std::string& etag);

// Answers with a kept JSON document and its ETag: 304 without a body when If-None-Match names the
// tag; otherwise 200 with `body` sent from where it is kept (`owner` keeps it alive) through a
// content provider of known length, which cpp-httplib sends as it is: no copy and no compression
// per request. A non-empty `content_encoding` (e.g. "gzip") says how `body` is already encoded.
void send_kept_json(const httplib::Request& request, httplib::Response& response, const std::string& etag,
                    std::shared_ptr<const void> owner, const std::string& body,
                    const std::string& content_encoding = "");
// The same for a kept body of any content type.
void send_kept(const httplib::Request& request, httplib::Response& response, const std::string& etag,
               std::shared_ptr<const void> owner, const std::string& body, const std::string& content_type,
               const std::string& content_encoding = "");

// Whether the request's Accept-Encoding names gzip.
bool accepts_gzip(const httplib::Request& request);

// A successful answer of text, JSON or JavaScript goes out gzip-compressed when it is 1 kB or more
// and the client accepts gzip, and as it is otherwise, through a content provider of known length,
// which cpp-httplib sends untouched: left to itself, cpp-httplib compresses every such answer on every
// request with Brotli at quality 11 (60 to 130 ms for a 15 kB page of the case table on a loaded
// 2-core machine, over a second for the 145 kB plotting library; docs/PERFORMANCE.md, "Dashboard").
void compress_answer(const httplib::Request& request, httplib::Response& response);

// Runs a handler, turning RequestError into its JSON answer, and compresses the answer.
template <typename Handler>
httplib::Server::Handler guarded(Handler handler) {
  return [handler](const httplib::Request& request, httplib::Response& response) {
    try {
      handler(request, response);
    } catch (const RequestError& error) {
      send_error(response, error);
    }
    compress_answer(request, response);
  };
}

}  // namespace aerobreak
