#pragma once
#include <span>
#include <string>
#include <string_view>

#include "orchestrator/service/endpoints.hpp"

namespace aerobreak {

// One endpoint of schemas/openapi.json: its method, its path as the description writes it ({id} a
// decimal id, {name} a fit's name), its operationId, and the function that answers it. `pattern`
// is the regular expression cpp-httplib matches when the path's own would not do (the dashboard's
// files); empty: made from the path.
struct Route {
  std::string_view method;
  std::string_view path;
  std::string_view operation_id;
  EndpointHandler handler;
  const char* pattern = nullptr;
};

// Every endpoint the service answers, one line each (routes.cpp); the tests check them against
// schemas/openapi.json.
std::span<const Route> routes();

// The regular expression cpp-httplib matches for a route.
std::string route_pattern(const Route& route);

// Registers every route on `server`, each answering with `endpoints` (guarded: a RequestError
// becomes its JSON answer).
void register_routes(httplib::Server& server, Endpoints& endpoints);

}  // namespace aerobreak
