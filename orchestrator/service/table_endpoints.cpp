#include "orchestrator/service/table_endpoints.hpp"

#include "orchestrator/export/table_formats.hpp"
#include "orchestrator/service/http_support.hpp"
#include "orchestrator/service/study_tables.hpp"

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

}  // namespace

namespace endpoint {

void get_study_table(Endpoints& e, const httplib::Request& request, httplib::Response& response) {
  const auto study = existing_study(e.store, path_id(request));
  try {
    const auto export_request = parse_export_request(query_parameters(request));
    const auto table = export_lookup_table(e.store, study, export_request);
    auto rendered = render_table(table, export_request, study.id);
    response.set_header("Content-Disposition", "attachment; filename=\"" + rendered.file_name + "\"");
    response.set_content(std::move(rendered.content), rendered.content_type);
  } catch (const ExportError& error) {
    throw request_error(error);
  }
}

}  // namespace endpoint
}  // namespace aerobreak
