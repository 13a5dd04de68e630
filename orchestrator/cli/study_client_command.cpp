#include "orchestrator/cli/study_client_command.hpp"

#include <httplib.h>

#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>

#include "orchestrator/cli/exit_codes.hpp"
#include "engine/impact/outcome.hpp"
#include "engine/io/bounded_input.hpp"
#include "orchestrator/cli/correlation_table.hpp"
#include "orchestrator/cli/outcome_table.hpp"
#include "orchestrator/study/study_axes.hpp"

namespace aerobreak {
namespace {

struct ClientOptions {
  std::string url;
  std::string token_file;
  std::string study_file;
  long long study_id = 0;
  std::string outcome;
  std::string fit;
  std::string covariates;
  bool default_covariates = true;
  std::size_t limit = 100;
  std::size_t offset = 0;
  bool json = false;
};

// The service answered with an error status; its JSON body names why.
struct ServiceRefusal {
  int status;
  nlohmann::ordered_json body;
};

struct ServiceUnreachable {
  std::string message;
};

// Why a request got no answer, as a sentence (httplib names only the kind of error: "Connection").
std::string unreachable_reason(httplib::Error error) {
  switch (error) {
    case httplib::Error::Connection:
      return "nothing accepts connections there.\n  Start a service with `aerobreak serve` (or keep the one of a run "
             "up with `aerobreak run STUDY.json --keep-serving`),\n  or give its address with --url or AEROBREAK_URL.";
    case httplib::Error::ConnectionTimeout:
      return "no connection within 5 s (is the address right, and reachable?)";
    case httplib::Error::Read:
      return "the connection broke before the whole answer came";
    case httplib::Error::Write:
      return "the connection broke while the request was sent";
    case httplib::Error::SSLConnection:
    case httplib::Error::SSLLoadingCerts:
    case httplib::Error::SSLServerVerification:
      return "the TLS connection failed (" + httplib::to_string(error) + ")";
    default:
      return "the request failed (" + httplib::to_string(error) + ")";
  }
}

std::string environment_or(const char* name, const std::string& fallback) {
  const char* value = std::getenv(name);
  return value && *value ? value : fallback;
}

class ApiClient {
 public:
  explicit ApiClient(const ClientOptions& options)
      : url_(options.url.empty() ? environment_or("AEROBREAK_URL", "http://127.0.0.1:8080") : options.url),
        client_(url_) {
    client_.set_connection_timeout(5, 0);
    client_.set_read_timeout(60, 0);
    std::string token = environment_or("AEROBREAK_TOKEN", "");
    if (!options.token_file.empty()) token = read_first_line(options.token_file, "token file");
    if (!token.empty()) headers_.emplace("Authorization", "Bearer " + token);
  }

  nlohmann::ordered_json get(const std::string& path) { return answer(client_.Get(path.c_str(), headers_), path); }
  nlohmann::ordered_json post(const std::string& path, const std::string& body) {
    return answer(client_.Post(path.c_str(), headers_, body, "application/json"), path);
  }

 private:
  nlohmann::ordered_json answer(const httplib::Result& result, const std::string& path) {
    if (!result)
      throw ServiceUnreachable{"no answer from the service at " + url_ + ": " + unreachable_reason(result.error())};
    nlohmann::ordered_json body = nlohmann::ordered_json::parse(result->body, nullptr, false);
    if (result->status >= 400) throw ServiceRefusal{result->status, body};
    if (body.is_discarded()) throw ServiceUnreachable{url_ + path + " did not answer with JSON"};
    return body;
  }

  std::string url_;
  httplib::Client client_;
  httplib::Headers headers_;
};

std::string study_path(long long id, const std::string& tail = {}) {
  return "/api/studies/" + std::to_string(id) + tail;
}

void print_progress(const nlohmann::ordered_json& progress) {
  const auto& counts = progress.at("counts");
  std::cout << "study " << progress.at("study") << ": " << progress.at("total") << " cases";
  for (const auto& [status, count] : counts.items()) std::cout << ", " << count << " " << status;
  if (progress.at("cases_per_hour").get<double>() > 0.0)
    std::cout << "; " << static_cast<long long>(progress.at("cases_per_hour").get<double>()) << " cases/h";
  if (!progress.at("seconds_left").is_null() && !progress.at("complete").get<bool>())
    std::cout << ", about " << static_cast<long long>(progress.at("seconds_left").get<double>()) << " s left";
  std::cout << (progress.at("complete").get<bool>() ? " (complete)" : "") << "\n";
}

// The study's unit system as the service names it (its "units": physical, reduced or mixed).
std::string unit_system(ApiClient& api, const ClientOptions& options) {
  return api.get(study_path(options.study_id)).at("units").at("system").get<std::string>();
}

// The study's fits: the critical speeds and energies and the list of fits; one fit in full (JSON)
// with --fit NAME.
void print_correlations(ApiClient& api, const ClientOptions& options) {
  std::string path = study_path(options.study_id, "/correlations");
  if (!options.fit.empty()) path += "/" + httplib::detail::encode_query_param(options.fit);
  if (!options.default_covariates) path += "?covariates=" + httplib::detail::encode_query_param(options.covariates);
  const auto answer = api.get(path);
  if (options.json || !options.fit.empty()) {
    std::cout << answer.dump(2) << "\n";
    return;
  }
  const auto& provenance = answer.at("provenance");
  const std::string system = unit_system(api, options);
  std::cout << "Correlations of study " << provenance.at("study") << " (result set "
            << provenance.at("result_set_hash").get<std::string>().substr(0, 12) << ", aerobreak "
            << provenance.at("aerobreak_version").get<std::string>() << ")\n\n"
            << "Critical speeds in " << speed_unit_label(system) << ":\n"
            << format_critical_table(answer, "impact_speed", system) << "\n"
            << "Critical energies per contact E_kin/(N_c E_break) (dimensionless):\n"
            << format_critical_table(answer, "energy_per_contact", system) << "\n"
            << critical_table_legend() << "\nFits (GET " << study_path(options.study_id, "/correlations/NAME")
            << " for one in full):\n"
            << format_fit_list(answer);
}

int run_client(const std::string& action, const ClientOptions& options) {
  ApiClient api(options);
  if (action == "submit") {
    const std::string study = read_regular_file(options.study_file, kMaxDocumentBytes, "study file");
    const auto receipt = api.post("/api/studies", study);
    if (options.json) {
      std::cout << receipt.dump(2) << "\n";
    } else {
      std::cout << "study " << receipt.at("id")
                << (receipt.at("existing_study").get<bool>() ? " (submitted before)" : "") << ": "
                << receipt.at("cases") << " cases, " << receipt.at("new_cases") << " new, "
                << receipt.at("already_done") << " already done\n";
    }
  } else if (action == "list") {
    const auto page =
        api.get("/api/studies?limit=" + std::to_string(options.limit) + "&offset=" + std::to_string(options.offset));
    if (options.json)
      std::cout << page.dump(2) << "\n";
    else
      for (const auto& study : page.at("items"))
        std::cout << study.at("id") << "  " << study.at("status").get<std::string>() << "  " << study.at("cases")
                  << " cases  " << study.at("name").get<std::string>() << "\n";
  } else if (action == "status") {
    const auto progress = api.get(study_path(options.study_id, "/progress"));
    if (options.json)
      std::cout << progress.dump(2) << "\n";
    else
      print_progress(progress);
  } else if (action == "results") {
    if (options.json) {
      std::string query = "?limit=" + std::to_string(options.limit) + "&offset=" + std::to_string(options.offset);
      if (!options.outcome.empty()) query += "&outcome=" + options.outcome;
      std::cout << api.get(study_path(options.study_id, "/results") + query).dump(2) << "\n";
    } else {
      std::cout << format_outcome_table(api.get(study_path(options.study_id, "/outcomes")), unit_system(api, options));
    }
  } else if (action == "correlations") {
    print_correlations(api, options);
  } else if (action == "cancel") {
    print_progress(api.post(study_path(options.study_id, "/cancel"), ""));
  }
  return 0;
}

}  // namespace

void add_study_client_subcommands(CLI::App& study, int& exit_code) {
  auto options = std::make_shared<ClientOptions>();
  const auto add = [&](const std::string& name, const std::string& summary) {
    auto* command = study.add_subcommand(name, summary);
    command->add_option("--url", options->url, "Service URL [default: AEROBREAK_URL or http://127.0.0.1:8080]");
    command->add_option("--token-file", options->token_file,
                        "File whose first line is the bearer token [AEROBREAK_TOKEN]");
    command->add_flag("--json", options->json, "Print the service's JSON answer");
    command->callback([name, options, &exit_code] {
      try {
        exit_code = run_client(name, *options);
      } catch (const ServiceRefusal& refusal) {
        std::cerr << "aerobreak study " << name << ": the service answered " << refusal.status << ": "
                  << (refusal.body.is_object() ? refusal.body.value("error", std::string("(no message)"))
                                               : std::string("(no JSON body)"))
                  << "\n";
        if (refusal.body.is_object() && refusal.body.contains("violations"))
          for (const auto& violation : refusal.body.at("violations"))
            std::cerr << "  "
                      << (violation.value("pointer", std::string()).empty() ? "(document)"
                                                                            : violation.value("pointer", std::string()))
                      << ": " << violation.value("message", std::string()) << "\n";
        exit_code = kExitInvalidInput;
      } catch (const ServiceUnreachable& unreachable) {
        std::cerr << "aerobreak study " << name << ": " << unreachable.message << "\n";
        exit_code = kExitUnreachable;
      } catch (const std::exception& error) {
        std::cerr << "aerobreak study " << name << ": " << error.what() << "\n";
        exit_code = kExitError;
      }
    });
    return command;
  };
  add("submit", "Submit a study to the service")
      ->add_option("study", options->study_file, "Study file (schemas/study.schema.json)")
      ->required()
      ->check(CLI::ExistingFile);
  auto* list = add("list", "List the service's studies, newest first");
  list->add_option("--limit", options->limit, "Studies per page")->capture_default_str();
  list->add_option("--offset", options->offset, "Studies to skip")->capture_default_str();
  add("status", "A study's progress: counts by status, rate, time left")
      ->add_option("id", options->study_id, "Study id")
      ->required();
  auto* results = add("results", "A study's outcome table (or, with --json, its results page)");
  results->add_option("id", options->study_id, "Study id")->required();
  results->add_option("--outcome", options->outcome, "With --json: only this outcome")
      ->check(CLI::IsMember(outcome_names()));
  results->add_option("--limit", options->limit, "With --json: results per page")->capture_default_str();
  results->add_option("--offset", options->offset, "With --json: results to skip")->capture_default_str();
  auto* correlations =
      add("correlations", "A study's fitted correlations: critical speeds and energies, and every fit");
  correlations->add_option("id", options->study_id, "Study id")->required();
  correlations->add_option("--fit", options->fit, "One fit in full, as JSON (a name from the list)");
  correlations
      ->add_option("--covariates", options->covariates,
                   "Covariates of the pooled models: axes of the study, by name or as " + known_covariate_names() +
                       "; e.g. gamma_over_kn,N (default: N where the study sweeps it)")
      ->each([options](const std::string&) { options->default_covariates = false; });
  add("cancel", "Cancel a study: its queued cases will not run")
      ->add_option("id", options->study_id, "Study id")
      ->required();
}

}  // namespace aerobreak
