#include "orchestrator/service/table_endpoints.hpp"

#include <algorithm>

#include "orchestrator/export/table_formats.hpp"
#include "orchestrator/service/http_support.hpp"

namespace aerobreak {
namespace {

std::vector<std::pair<std::string, std::string>> query_parameters(const httplib::Request& request) {
  if (request.params.size() > kMaxExportParameters)
    throw RequestError{400, "at most " + std::to_string(kMaxExportParameters) + " query parameters"};
  return {request.params.begin(), request.params.end()};
}

RequestError request_error(const ExportError& error) {
  return {error.status, error.what(),
          nlohmann::ordered_json::array({{{"parameter", error.field}, {"message", error.what()}}})};
}

// The request's canonical text: its parameters sorted (the key of a kept file).
std::string request_key(std::vector<std::pair<std::string, std::string>> parameters) {
  std::sort(parameters.begin(), parameters.end());
  std::string key;
  for (const auto& [name, value] : parameters) key += name + "=" + value + "\n";
  return key;
}

}  // namespace

namespace endpoint {

void get_study_table(Endpoints& e, const httplib::Request& request, httplib::Response& response) {
  const auto study = existing_study(e.store, path_id(request));
  try {
    const auto parameters = query_parameters(request);
    const auto kept = e.tables.file(study, parse_export_request(parameters), request_key(parameters));
    response.set_header("Content-Disposition", "attachment; filename=\"" + kept->file.file_name + "\"");
    response.set_header("Vary", "Accept-Encoding");
    if (accepts_gzip(request))
      send_kept(request, response, kept->etag, kept, kept->gzip_body, kept->file.content_type, "gzip");
    else
      send_kept(request, response, kept->etag, kept, kept->file.content, kept->file.content_type);
  } catch (const ExportError& error) {
    throw request_error(error);
  }
}

}  // namespace endpoint
}  // namespace aerobreak
