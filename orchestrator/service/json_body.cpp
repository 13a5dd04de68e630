#include "orchestrator/service/json_body.hpp"

#include <string>

#include "orchestrator/service/http_support.hpp"

namespace aerobreak {

nlohmann::ordered_json parse_json_body(std::string_view body, std::size_t max_depth) {
  try {
    return parse_json_text(body, max_depth);
  } catch (const JsonTextError& error) {
    throw RequestError{400, "the body is refused: " + error.problem(),
                       nlohmann::ordered_json::array({{{"pointer", ""}, {"message", error.what()}}})};
  } catch (const nlohmann::json::exception& error) {
    // parse_error for the syntax, out_of_range for a number beyond a double (1e999).
    throw RequestError{400, "the body is not JSON",
                       nlohmann::ordered_json::array({{{"pointer", ""}, {"message", error.what()}}})};
  }
}

}  // namespace aerobreak
