#include "orchestrator/service/http_api.hpp"

#include <httplib.h>

#include <optional>
#include <string>

#include "engine/core/version.hpp"
#include "orchestrator/service/api_json.hpp"
#include "orchestrator/service/correlation_endpoints.hpp"
#include "orchestrator/service/dashboard_endpoints.hpp"
#include "orchestrator/service/http_support.hpp"
#include "orchestrator/service/openapi_text.hpp"
#include "orchestrator/service/study_submission.hpp"
#include "orchestrator/service/summary_endpoints.hpp"
#include "orchestrator/service/table_endpoints.hpp"
#include "orchestrator/service/web_endpoints.hpp"

namespace aerobreak {
namespace {

// Compares without an early exit, so that response times do not reveal how much of a guess was right.
bool same_token(const std::string& given, const std::string& expected) {
  unsigned char difference = given.size() == expected.size() ? 0 : 1;
  for (std::size_t i = 0; i < given.size(); ++i)
    difference |= static_cast<unsigned char>(given[i] ^ expected[i % std::max<std::size_t>(expected.size(), 1)]);
  return difference == 0;
}

void submit_study(const httplib::Request& request, httplib::Response& response, Store& store, Scheduler* scheduler,
                  const ServiceOptions& options) {
  nlohmann::ordered_json document;
  try {
    document = nlohmann::ordered_json::parse(request.body);
  } catch (const nlohmann::json::parse_error& error) {
    throw RequestError{400, "the body is not JSON", nlohmann::ordered_json::array({{{"pointer", ""},
                                                                                  {"message", error.what()}}})};
  }
  try {
    const Study study = parse_study(std::move(document), options.study_limits);
    const auto receipt = store.submit_study(make_submission(study));
    if (scheduler) scheduler->wake();
    response.set_header("Location", "/api/studies/" + std::to_string(receipt.study_id));
    send_json(response, receipt.existing_study ? 200 : 201, to_json(receipt));
  } catch (const StudyError& error) {
    throw RequestError{422, "the study is not valid", violations_json(error.violations())};
  }
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
                       {"job",
                        status.job_running ? nlohmann::ordered_json{{"id", status.job_id},
                                                                     {"pid", status.job_pid},
                                                                     {"ready", status.job_ready},
                                                                     {"ranks", status.ranks},
                                                                     {"in_flight", status.in_flight}}
                                           : nlohmann::ordered_json(nullptr)},
                       {"jobs_started", status.jobs_started},
                       {"results_committed", status.results_committed},
                       {"consecutive_launch_failures", status.consecutive_launch_failures},
                       {"last_error", status.last_error.empty() ? nlohmann::ordered_json(nullptr)
                                                                : nlohmann::ordered_json(status.last_error)}};
  if (status.consecutive_launch_failures > 0) json["status"] = "degraded";
  return json;
}

}  // namespace

void register_http_api(httplib::Server& server, Store& store, Scheduler* scheduler, const ServiceOptions& options) {
  const bool token_required = options.token.has_value();
  server.set_pre_routing_handler([&options, token_required](const httplib::Request& request, httplib::Response& response) {
    if (!token_required || request.method == "GET" || request.method == "HEAD") return httplib::Server::HandlerResponse::Unhandled;
    const std::string header = request.get_header_value("Authorization");
    const std::string prefix = "Bearer ";
    if (header.rfind(prefix, 0) == 0 && same_token(header.substr(prefix.size()), *options.token))
      return httplib::Server::HandlerResponse::Unhandled;
    response.set_header("WWW-Authenticate", "Bearer");
    send_error(response, {401, "this endpoint needs 'Authorization: Bearer TOKEN'"});
    return httplib::Server::HandlerResponse::Handled;
  });
  server.set_error_handler([](const httplib::Request& request, httplib::Response& response) {
    if (!response.body.empty()) return;
    if (response.status == 413)
      send_error(response, {413, "the request body is larger than the service accepts"});
    else if (response.status == 404)
      send_error(response, {404, "no endpoint " + request.method + " " + request.path + " (see /api/openapi.json)"});
    else
      send_error(response, {response.status, "the request could not be served"});
  });
  server.set_exception_handler([](const httplib::Request&, httplib::Response& response, std::exception_ptr error) {
    std::string message = "internal error";
    try {
      std::rethrow_exception(error);
    } catch (const std::exception& e) {
      message += std::string(": ") + e.what();
    } catch (...) {
    }
    send_error(response, {500, message});
  });

  server.Get("/api/health", guarded([&store, scheduler](const httplib::Request&, httplib::Response& response) {
    send_json(response, 200, health(store, scheduler));
  }));
  server.Get("/api/openapi.json", [](const httplib::Request&, httplib::Response& response) {
    response.set_content(std::string(openapi_text()), "application/json");
  });
  server.Get("/api/studies", guarded([&store, &options](const httplib::Request& request, httplib::Response& response) {
    const auto page = page_request(request, options);
    const auto studies = store.studies(page);
    nlohmann::ordered_json items = nlohmann::ordered_json::array();
    for (const auto& study : studies.items) items.push_back(to_json(study, false));
    send_json(response, 200,
              {{"total", studies.total}, {"limit", page.limit}, {"offset", page.offset}, {"items", items}});
  }));
  server.Post("/api/studies",
              guarded([&store, scheduler, &options](const httplib::Request& request, httplib::Response& response) {
                submit_study(request, response, store, scheduler, options);
              }));
  server.Get(R"(/api/studies/(\d+))", guarded([&store](const httplib::Request& request, httplib::Response& response) {
    const auto study = existing_study(store, path_id(request));
    auto json = to_json(study, true);
    json["progress"] = to_json(*store.progress(study.id));
    send_json(response, 200, json);
  }));
  server.Get(R"(/api/studies/(\d+)/cases)",
             guarded([&store, &options](const httplib::Request& request, httplib::Response& response) {
               const auto study = existing_study(store, path_id(request));
               std::optional<CaseStatus> status;
               if (request.has_param("status")) {
                 status = parse_case_status(request.get_param_value("status"));
                 if (!status)
                   throw RequestError{400, "query parameter 'status' must be queued, running, done, failed or cancelled"};
               }
               const auto page = page_request(request, options);
               send_json(response, 200, page_json(store.cases(study.id, status, page), page));
             }));
  server.Get(R"(/api/studies/(\d+)/results)",
             guarded([&store, &options](const httplib::Request& request, httplib::Response& response) {
               const auto study = existing_study(store, path_id(request));
               std::optional<std::string> outcome;
               if (request.has_param("outcome")) {
                 outcome = request.get_param_value("outcome");
                 if (*outcome != "stick" && *outcome != "bounce" && *outcome != "break-up" && *outcome != "undetermined")
                   throw RequestError{400, "query parameter 'outcome' must be stick, bounce, break-up or undetermined"};
               }
               const auto page = page_request(request, options);
               send_json(response, 200, page_json(store.results(study.id, outcome, page), page));
             }));
  register_summary_endpoints(server, store);
  register_table_endpoints(server, store);
  register_correlation_endpoints(server, store);
  server.Post(R"(/api/studies/(\d+)/cancel)",
              guarded([&store](const httplib::Request& request, httplib::Response& response) {
                const auto study = existing_study(store, path_id(request));
                if (!store.cancel_study(study.id))
                  throw RequestError{409, "study " + std::to_string(study.id) + " is already cancelled"};
                send_json(response, 200, to_json(*store.progress(study.id)));
              }));
  server.Get(R"(/api/cases/(\d+))", guarded([&store](const httplib::Request& request, httplib::Response& response) {
    const auto detail = store.case_detail(path_id(request));
    if (!detail) throw RequestError{404, "no case " + std::string(request.matches[1])};
    send_json(response, 200, to_json(*detail));
  }));
  server.Get("/api/jobs", guarded([&store, &options](const httplib::Request& request, httplib::Response& response) {
    const auto limit = unsigned_parameter(request, "limit", 20, options.max_page_size);
    nlohmann::ordered_json items = nlohmann::ordered_json::array();
    for (const auto& job : store.jobs(limit)) items.push_back(to_json(job));
    send_json(response, 200, {{"items", items}});
  }));
  register_dashboard_endpoints(server, store, options);
  register_web_endpoints(server, options);
}

}  // namespace aerobreak
