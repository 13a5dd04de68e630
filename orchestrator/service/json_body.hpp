#pragma once
#include <cstddef>
#include <string_view>

#include <nlohmann/json.hpp>

namespace aerobreak {

// The deepest nesting of arrays and objects a request body may have. A study is 5 levels deep;
// nlohmann parses without recursion, but it copies, compares and writes values recursively, as
// does the schema validator, so that 100,000 levels overflow a thread's stack.
constexpr std::size_t kMaxJsonDepth = 64;

// A request body as JSON. Before anything recursive runs, one pass over the bytes checks that the
// body is UTF-8 (RFC 8259 8.1: no byte-order mark, no UTF-16, no invalid sequence) and nests at
// most `max_depth` levels; then nlohmann parses it. Throws RequestError 400 naming the problem and
// its byte offset, also for a number that no double holds (1e999).
nlohmann::ordered_json parse_json_body(std::string_view body, std::size_t max_depth = kMaxJsonDepth);

}  // namespace aerobreak
