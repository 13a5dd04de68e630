#include "orchestrator/service/error_answers.hpp"

#include <string>

#include "orchestrator/service/bounded_server.hpp"
#include "orchestrator/service/http_support.hpp"
#include "orchestrator/store/sqlite_database.hpp"

namespace aerobreak {

void answer_error(const httplib::Request& request, httplib::Response& response) {
  if (const RequestFault* fault = current_request_fault()) {
    send_error(response, {fault->status, fault->message});
    close_connection_after_response(response);
  } else if (!response.body.empty()) {
    return;
  } else if (response.status == 413) {
    send_error(response, {413, "the request body is larger than the service accepts"});
  } else if (response.status == 404) {
    send_error(response, {404, "no endpoint " + request.method + " " + request.path + " (see /api/openapi.json)"});
  } else {
    send_error(response, {response.status, "the request could not be served"});
  }
}

void answer_exception(const httplib::Request&, httplib::Response& response, std::exception_ptr error) {
  try {
    std::rethrow_exception(error);
  } catch (const SqliteError& e) {
    if (e.storage_fault())
      send_error(response, {503, std::string("the store cannot be written just now; try again later: ") + e.what()});
    else
      send_error(response, {500, std::string("internal error: ") + e.what()});
  } catch (const std::exception& e) {
    send_error(response, {500, std::string("internal error: ") + e.what()});
  } catch (...) {
    send_error(response, {500, "internal error"});
  }
}

}  // namespace aerobreak
