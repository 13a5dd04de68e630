#include "engine/io/json_text.hpp"

namespace aerobreak {
namespace {

// The length of the UTF-8 sequence that starts at bytes[at]; 0 when it is not a valid one
// (RFC 3629 4: no overlong forms, no UTF-16 surrogates, nothing above U+10FFFF).
std::size_t utf8_sequence_length(std::string_view bytes, std::size_t at) {
  const auto lead = static_cast<unsigned char>(bytes[at]);
  if (lead < 0x80) return 1;
  std::size_t length = 0;
  unsigned char low = 0x80, high = 0xBF;  // the allowed range of the second byte
  if (lead >= 0xC2 && lead <= 0xDF)
    length = 2;
  else if (lead == 0xE0)
    length = 3, low = 0xA0;
  else if ((lead >= 0xE1 && lead <= 0xEC) || lead == 0xEE || lead == 0xEF)
    length = 3;
  else if (lead == 0xED)
    length = 3, high = 0x9F;
  else if (lead == 0xF0)
    length = 4, low = 0x90;
  else if (lead >= 0xF1 && lead <= 0xF3)
    length = 4;
  else if (lead == 0xF4)
    length = 4, high = 0x8F;
  else
    return 0;
  if (at + length > bytes.size()) return 0;
  const auto second = static_cast<unsigned char>(bytes[at + 1]);
  if (second < low || second > high) return 0;
  for (std::size_t k = 2; k < length; ++k) {
    const auto next = static_cast<unsigned char>(bytes[at + k]);
    if (next < 0x80 || next > 0xBF) return 0;
  }
  return length;
}

void check_encoding_marks(std::string_view text) {
  if (text.starts_with("\xEF\xBB\xBF"))
    throw JsonTextError("it starts with a byte-order mark, which JSON text must not have", 0);
  if (text.starts_with("\xFE\xFF") || text.starts_with("\xFF\xFE"))
    throw JsonTextError("it is UTF-16 (it starts with a UTF-16 byte-order mark); send UTF-8", 0);
}

}  // namespace

void check_json_text(std::string_view text, std::size_t max_depth) {
  check_encoding_marks(text);
  std::size_t depth = 0;
  bool in_string = false;
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t length = utf8_sequence_length(text, at);
    if (length == 0) throw JsonTextError("it is not valid UTF-8", at);
    const char c = text[at];
    if (in_string) {
      if (c == '\\') {
        at += 1 + (at + 1 < text.size() && static_cast<unsigned char>(text[at + 1]) < 0x80);
        continue;
      }
      if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > max_depth)
        throw JsonTextError("arrays and objects nest deeper than " + std::to_string(max_depth) + " levels", at);
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
    at += length;
  }
}

nlohmann::ordered_json parse_json_text(std::string_view text, std::size_t max_depth) {
  check_json_text(text, max_depth);
  return nlohmann::ordered_json::parse(text);
}

nlohmann::ordered_json read_json_file(const std::filesystem::path& path, std::string_view what,
                                      std::uintmax_t max_bytes) {
  const std::string text = read_regular_file(path, max_bytes, what);
  const std::string named = std::string(what) + " " + path.string();
  try {
    return parse_json_text(text);
  } catch (const JsonTextError& error) {
    throw InputFileError(named + ": " + error.what());
  } catch (const nlohmann::json::out_of_range& error) {
    throw InputFileError(named + ": a number is beyond what a double holds: " + error.what());
  } catch (const nlohmann::json::exception& error) {
    throw InputFileError(named + " is not valid JSON: " + error.what());
  }
}

}  // namespace aerobreak
