#pragma once
#include <cstddef>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "engine/io/bounded_input.hpp"

namespace aerobreak {

// JSON text as the service and the command line accept it, checked before anything recursive
// runs: the same rules for a request body and for every JSON file the program reads.

// The deepest nesting of arrays and objects accepted. A study is 5 levels deep; nlohmann parses
// without recursion, but it copies, compares and writes values recursively, as does the schema
// validator, so that 100,000 levels overflow a thread's stack.
constexpr std::size_t kMaxJsonDepth = 64;

// Text that is not acceptable JSON: the problem and the byte offset where it was found.
class JsonTextError : public std::runtime_error {
 public:
  JsonTextError(std::string problem, std::size_t offset)
      : std::runtime_error(problem + " (at byte " + std::to_string(offset) + ")"),
        problem_(std::move(problem)),
        offset_(offset) {}
  const std::string& problem() const { return problem_; }
  std::size_t offset() const { return offset_; }

 private:
  std::string problem_;
  std::size_t offset_;
};

// One pass over the bytes: UTF-8 (RFC 8259 8.1: no byte-order mark, no UTF-16, no invalid
// sequence) with arrays and objects nested at most `max_depth` deep. Throws JsonTextError.
void check_json_text(std::string_view text, std::size_t max_depth = kMaxJsonDepth);

// check_json_text, then the parse. Throws JsonTextError for the checks, nlohmann::json::exception
// for the syntax and for a number that no double holds (1e999: out_of_range).
nlohmann::ordered_json parse_json_text(std::string_view text, std::size_t max_depth = kMaxJsonDepth);

// A JSON file a user names (a case, a study): read_regular_file within `max_bytes`, then
// parse_json_text. Throws InputFileError naming the file (as `what`) and the problem.
nlohmann::ordered_json read_json_file(const std::filesystem::path& path, std::string_view what,
                                      std::uintmax_t max_bytes = kMaxDocumentBytes);

}  // namespace aerobreak
