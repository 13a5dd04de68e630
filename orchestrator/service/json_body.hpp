#pragma once
#include <cstddef>
#include <string_view>

#include <nlohmann/json.hpp>

#include "engine/io/json_text.hpp"

namespace aerobreak {

// A request body as JSON, by the rules every JSON text the program reads follows
// (engine/io/json_text.hpp): before anything recursive runs, one pass over the bytes checks that
// the body is UTF-8 (RFC 8259 8.1: no byte-order mark, no UTF-16, no invalid sequence) and nests
// at most `max_depth` levels; then nlohmann parses it. Throws RequestError 400 naming the problem
// and its byte offset, also for a number that no double holds (1e999).
nlohmann::ordered_json parse_json_body(std::string_view body, std::size_t max_depth = kMaxJsonDepth);

}  // namespace aerobreak
