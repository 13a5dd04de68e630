#pragma once
#include <httplib.h>

#include <exception>

// How the service answers requests that no endpoint answered itself.
namespace aerobreak {

// The error handler: a request the library could not serve gets a JSON body saying why (408 or
// 431 for one that arrived too slowly or with too many header bytes, 404 naming the path, 413).
void answer_error(const httplib::Request& request, httplib::Response& response);

// The exception handler: 503 when the store cannot be written just now (disk full, read-only, I/O
// error: the request can be repeated once that is mended), 500 for anything else.
void answer_exception(const httplib::Request& request, httplib::Response& response, std::exception_ptr error);

}  // namespace aerobreak
