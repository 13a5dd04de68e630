#include "orchestrator/service/http_api.hpp"

#include <httplib.h>

#include <optional>
#include <string>

#include "engine/core/version.hpp"
#include "orchestrator/app/study_submission.hpp"
#include "orchestrator/service/access_log.hpp"
#include "orchestrator/service/api_json.hpp"
#include "orchestrator/service/byte_ranges.hpp"
#include "orchestrator/service/error_answers.hpp"
#include "orchestrator/service/http_support.hpp"
#include "orchestrator/service/json_body.hpp"
#include "orchestrator/service/openapi_text.hpp"
#include "orchestrator/service/request_checks.hpp"
#include "orchestrator/service/routes.hpp"
#include "orchestrator/service/study_templates.hpp"

namespace aerobreak {
namespace {

nlohmann::ordered_json storage_fault_json(const std::optional<StorageFaultStatus>& fault) {
  if (!fault) return nullptr;
  return {{"error", fault->error}, {"since", fault->since}, {"waiting_writes", fault->waiting_writes}};
}

nlohmann::ordered_json health(Store& store, Scheduler* scheduler) {
  nlohmann::ordered_json json{{"status", "ok"},
                              {"version", std::string(version())},
                              {"commit", std::string(git_commit())},
                              {"store", {{"file", store.file().string()}, {"schema_version", store.schema_version()}}},
                              {"queued_cases", store.claimable_cases()}};
  if (!scheduler) {
    json["scheduler"] = nullptr;
    return json;
  }
  const auto status = scheduler->status();
  json["scheduler"] = {{"launcher", status.launcher_command},
                       {"job", status.job_running ? nlohmann::ordered_json{{"id", status.job_id},
                                                                           {"pid", status.job_pid},
                                                                           {"ready", status.job_ready},
                                                                           {"ranks", status.ranks},
                                                                           {"in_flight", status.in_flight}}
                                                  : nlohmann::ordered_json(nullptr)},
                       {"jobs_started", status.jobs_started},
                       {"results_committed", status.results_committed},
                       {"consecutive_launch_failures", status.consecutive_launch_failures},
                       {"last_error", status.last_error.empty() ? nlohmann::ordered_json(nullptr)
                                                                : nlohmann::ordered_json(status.last_error)},
                       {"storage_fault", storage_fault_json(status.storage_fault)}};
  if (status.consecutive_launch_failures > 0 || status.storage_fault) json["status"] = "degraded";
  return json;
}

}  // namespace

namespace endpoint {

void get_health(Endpoints& e, const httplib::Request&, httplib::Response& response) {
  send_json(response, 200, health(e.store, e.scheduler));
}

void get_openapi(Endpoints&, const httplib::Request&, httplib::Response& response) {
  response.set_content(std::string(openapi_text()), "application/json");
}

void get_templates(Endpoints&, const httplib::Request&, httplib::Response& response) {
  send_json(response, 200, study_templates_json());
}

void get_case_fields(Endpoints&, const httplib::Request&, httplib::Response& response) {
  static const nlohmann::ordered_json fields = case_fields_json();
  send_json(response, 200, fields);
}

void list_studies(Endpoints& e, const httplib::Request& request, httplib::Response& response) {
  const auto page = page_request(request, e.options);
  const auto studies = e.store.studies(page);
  nlohmann::ordered_json items = nlohmann::ordered_json::array();
  for (const auto& study : studies.items) items.push_back(to_json(study, false));
  send_json(response, 200,
            {{"total", studies.total}, {"limit", page.limit}, {"offset", page.offset}, {"items", items}});
}

void submit_study(Endpoints& e, const httplib::Request& request, httplib::Response& response) {
  nlohmann::ordered_json document = parse_json_body(request.body);
  try {
    const Study study = parse_study(std::move(document), e.options.study_limits);
    const auto receipt =
        aerobreak::submit_study(study, e.store, e.data_files, flag_parameter(request, "recompute_data_files"));
    if (e.scheduler) e.scheduler->wake();
    response.set_header("Location", "/api/studies/" + std::to_string(receipt.study_id));
    send_json(response, receipt.existing_study ? 200 : 201, to_json(receipt));
  } catch (const StudyError& error) {
    throw RequestError{422, "the study is not valid", violations_json(error.violations())};
  }
}

void get_study(Endpoints& e, const httplib::Request& request, httplib::Response& response) {
  const auto study = existing_study(e.store, path_id(request));
  auto json = to_json(study, true);
  json["progress"] = to_json(*e.store.progress(study.id));
  send_json(response, 200, json);
}

void list_study_cases(Endpoints& e, const httplib::Request& request, httplib::Response& response) {
  const auto study = existing_study(e.store, path_id(request));
  const auto status = status_parameter(request);
  const auto page = page_request(request, e.options);
  send_json(response, 200, page_json(e.store.cases(study.id, status, page), page));
}

void list_study_results(Endpoints& e, const httplib::Request& request, httplib::Response& response) {
  const auto study = existing_study(e.store, path_id(request));
  const auto outcome = outcome_parameter(request);
  const auto page = page_request(request, e.options);
  send_json(response, 200, page_json(e.store.results(study.id, outcome, page), page));
}

void cancel_study(Endpoints& e, const httplib::Request& request, httplib::Response& response) {
  const auto study = existing_study(e.store, path_id(request));
  if (!e.store.cancel_study(study.id))
    throw RequestError{409, "study " + std::to_string(study.id) + " is already cancelled"};
  send_json(response, 200, to_json(*e.store.progress(study.id)));
}

void get_case(Endpoints& e, const httplib::Request& request, httplib::Response& response) {
  const auto detail = e.store.case_detail(path_id(request));
  if (!detail) throw RequestError{404, "no case " + std::string(request.matches[1])};
  std::optional<DataFileCheck> check;
  if (detail->data_file) check = e.data_files.check(*detail->data_file, detail->data_file_digest);
  send_json(response, 200, to_json(*detail, check));
}

void list_jobs(Endpoints& e, const httplib::Request& request, httplib::Response& response) {
  const auto limit = unsigned_parameter(request, "limit", 20, e.options.max_page_size);
  nlohmann::ordered_json items = nlohmann::ordered_json::array();
  for (const auto& job : e.store.jobs(limit)) items.push_back(to_json(job));
  send_json(response, 200, {{"items", items}});
}

}  // namespace endpoint

void register_http_api(httplib::Server& server, Endpoints& endpoints) {
  const ServiceOptions& options = endpoints.options;
  server.set_pre_routing_handler([&options](const httplib::Request& request, httplib::Response& response) {
    return check_request(request, response, options);
  });
  server.set_post_routing_handler(apply_byte_ranges);
  server.set_error_handler(answer_error);
  server.set_exception_handler(answer_exception);
  if (options.access_log) server.set_logger(access_logger(options.access_log));
  register_routes(server, endpoints);
}

}  // namespace aerobreak
