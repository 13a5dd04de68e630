#pragma once
#include <httplib.h>

#include <functional>
#include <string>

namespace aerobreak {

// cpp-httplib's logger as an access log: one line per request answered,
//   127.0.0.1:51234 "POST /api/studies" 201 12.3 ms
// (client, method and target as sent, status, milliseconds from the request's first byte to its
// answer). Bytes of the target outside printable ASCII are written \xHH and it is cut at 200
// characters, so that a request cannot forge or flood log lines.
httplib::Logger access_logger(std::function<void(const std::string&)> log);

}  // namespace aerobreak
