#pragma once
#include <httplib.h>

#include "orchestrator/service/service.hpp"

namespace aerobreak {

// Checks every request after its headers and before it is routed or its body is read, in order:
//   health only  on a slot kept for /api/health (connection_slots.hpp): GET or HEAD of it  503
//   framing      one Content-Length value, a number, no Transfer-Encoding; a method with a body
//                (POST, PUT, PATCH, DELETE) has a Content-Length within the body limit   400 411 413
//   origin       without a token: the Host header names a loopback address, so that a web
//                page whose name was rebound to 127.0.0.1 cannot read or write           403
//   token        with a token: all but GET and HEAD carry 'Authorization: Bearer TOKEN'  401
//   media type   without a token: a POST says Content-Type: application/json, which a web page
//                can only send to another site after a CORS preflight this service never
//                grants (forms and simple requests send text/plain or form encodings)    415
// Returns Handled with the JSON error answered and the connection closed after it (its body is
// never read), Unhandled for a request that passes.
httplib::Server::HandlerResponse check_request(const httplib::Request& request, httplib::Response& response,
                                               const ServiceOptions& options);

// The host part of a Host header value ("127.0.0.1:8080" -> "127.0.0.1", "[::1]:80" -> "::1").
std::string host_of(const std::string& host_header);

}  // namespace aerobreak
