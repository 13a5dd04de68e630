#include "orchestrator/service/json_body.hpp"

#include <string>

#include "orchestrator/service/http_support.hpp"

namespace aerobreak {
namespace {

[[noreturn]] void refuse(const std::string& problem, std::size_t offset) {
  throw RequestError{400, "the body is refused: " + problem,
                     nlohmann::ordered_json::array({{{"pointer", ""},
                                                     {"message", problem + " (at byte " + std::to_string(offset) + ")"}}})};
}

// The length of the UTF-8 sequence that starts at bytes[at]; 0 when it is not a valid one
// (RFC 3629 4: no overlong forms, no UTF-16 surrogates, nothing above U+10FFFF).
std::size_t utf8_sequence_length(std::string_view bytes, std::size_t at) {
  const auto lead = static_cast<unsigned char>(bytes[at]);
  if (lead < 0x80) return 1;
  std::size_t length = 0;
  unsigned char low = 0x80, high = 0xBF;  // the allowed range of the second byte
  if (lead >= 0xC2 && lead <= 0xDF) length = 2;
  else if (lead == 0xE0) length = 3, low = 0xA0;
  else if ((lead >= 0xE1 && lead <= 0xEC) || lead == 0xEE || lead == 0xEF) length = 3;
  else if (lead == 0xED) length = 3, high = 0x9F;
  else if (lead == 0xF0) length = 4, low = 0x90;
  else if (lead >= 0xF1 && lead <= 0xF3) length = 4;
  else if (lead == 0xF4) length = 4, high = 0x8F;
  else return 0;
  if (at + length > bytes.size()) return 0;
  const auto second = static_cast<unsigned char>(bytes[at + 1]);
  if (second < low || second > high) return 0;
  for (std::size_t k = 2; k < length; ++k) {
    const auto next = static_cast<unsigned char>(bytes[at + k]);
    if (next < 0x80 || next > 0xBF) return 0;
  }
  return length;
}

void check_encoding_marks(std::string_view body) {
  if (body.starts_with("\xEF\xBB\xBF")) refuse("it starts with a byte-order mark, which JSON text must not have", 0);
  if (body.starts_with("\xFE\xFF") || body.starts_with("\xFF\xFE"))
    refuse("it is UTF-16 (it starts with a UTF-16 byte-order mark); send UTF-8", 0);
}

// One pass: every byte part of a valid UTF-8 sequence, and arrays and objects (outside strings)
// nested at most max_depth deep.
void check_bytes(std::string_view body, std::size_t max_depth) {
  std::size_t depth = 0;
  bool in_string = false;
  for (std::size_t at = 0; at < body.size();) {
    const std::size_t length = utf8_sequence_length(body, at);
    if (length == 0) refuse("it is not valid UTF-8", at);
    const char c = body[at];
    if (in_string) {
      if (c == '\\') {
        at += 1 + (at + 1 < body.size() && static_cast<unsigned char>(body[at + 1]) < 0x80);
        continue;
      }
      if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > max_depth) refuse("arrays and objects nest deeper than " + std::to_string(max_depth) + " levels", at);
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
    at += length;
  }
}

}  // namespace

nlohmann::ordered_json parse_json_body(std::string_view body, std::size_t max_depth) {
  check_encoding_marks(body);
  check_bytes(body, max_depth);
  try {
    return nlohmann::ordered_json::parse(body);
  } catch (const nlohmann::json::exception& error) {
    // parse_error for the syntax, out_of_range for a number beyond a double (1e999).
    throw RequestError{400, "the body is not JSON",
                       nlohmann::ordered_json::array({{{"pointer", ""}, {"message", error.what()}}})};
  }
}

}  // namespace aerobreak
