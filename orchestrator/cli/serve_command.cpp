#include "orchestrator/cli/serve_command.hpp"

#include <signal.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>

#include "orchestrator/cli/exit_codes.hpp"
#include "engine/io/bounded_input.hpp"
#include "orchestrator/cli/orchestrator_options.hpp"
#include "orchestrator/service/service.hpp"

namespace aerobreak {
namespace {

OrchestratorOptions default_orchestrator_options() {
  OrchestratorOptions options;
  options.store = "runs/aerobreak.sqlite";
  return options;
}

struct ServeOptions {
  OrchestratorOptions orchestrator = default_orchestrator_options();
  std::string host = "127.0.0.1";
  int port = 8080;
  std::string token_file;
  std::string port_file;
  std::size_t max_cases = kServiceStudyLimits.max_cases;
  std::size_t max_primaries = kServiceStudyLimits.max_primaries;
  std::size_t max_connections = ConnectionLimits{}.max_connections;
  std::size_t max_connections_per_client = 0;  // 0: half of max_connections
  bool quiet = false;
};

std::string read_token(const std::string& path) {
  const std::string token = read_first_line(path, "token file");
  if (token.size() < 16) throw std::runtime_error("the token in " + path + " is shorter than 16 characters");
  return token;
}

// Written whole and renamed, so that a script waiting for the file never reads half a number.
void write_port_file(const std::string& path, int port) {
  const std::string partial = path + ".partial";
  std::ofstream out(partial);
  out << port << "\n";
  out.close();
  std::error_code error;
  if (out) std::filesystem::rename(partial, path, error);
  if (!out || error) {
    std::filesystem::remove(partial, error);
    throw std::runtime_error("cannot write the port file " + path + " (" +
                             (out ? error.message() : std::string(std::strerror(errno))) +
                             "): --port-file must name a "
                             "file in a folder this user can write");
  }
}

int serve(const ServeOptions& options) {
  ShutdownSignals signals;
  Store store(options.orchestrator.store, Store::Access::orchestrator, options.orchestrator.data_directory());
  const auto log = line_log({});
  Scheduler scheduler(store, options.orchestrator.scheduler_options(log));
  ServiceOptions service_options = options.orchestrator.service_options();
  service_options.host = options.host;
  service_options.port = options.port;
  service_options.connections.max_connections = options.max_connections;
  service_options.connections.max_connections_per_client = options.max_connections_per_client > 0
                                                               ? options.max_connections_per_client
                                                               : std::max<std::size_t>(1, options.max_connections / 2);
  if (!options.quiet) service_options.access_log = log;
  if (!options.token_file.empty()) service_options.token = read_token(options.token_file);
  service_options.study_limits.max_cases = options.max_cases;
  service_options.study_limits.max_primaries = options.max_primaries;
  Service service(store, &scheduler, service_options);
  service.start();
  if (!options.port_file.empty()) write_port_file(options.port_file, service.port());
  scheduler.start();
  std::cerr << "aerobreak serve: " << service.url() << "/  (store " << store.file().string() << ", schema version "
            << store.schema_version() << "; workers: " << scheduler.status().launcher_command << ")" << std::endl;
  const int received = signals.wait();
  std::cerr << "aerobreak serve: " << (received == SIGINT ? "SIGINT" : "SIGTERM")
            << ": stopping; running cases go back to the queue" << std::endl;
  service.stop();
  scheduler.stop();
  return 0;
}

}  // namespace

void add_serve_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<ServeOptions>();
  auto* command = app.add_subcommand("serve", "Start the orchestrator service: REST API, store and worker jobs");
  options->orchestrator.add_to(*command);
  command->add_option("--host", options->host, "Address to listen on; beyond loopback a token is required")
      ->capture_default_str();
  command->add_option("--port", options->port, "TCP port (0: any free port)")
      ->check(CLI::Range(0, 65535))
      ->capture_default_str();
  command->add_option("--token-file", options->token_file,
                      "File whose first line is the bearer token that POST requests must carry");
  command->add_option("--port-file", options->port_file, "Write the port listened on to this file once serving");
  command->add_option("--max-cases", options->max_cases, "Largest study (cases) a client may submit")
      ->capture_default_str();
  command->add_option("--max-primaries", options->max_primaries, "Largest cluster a client may ask for")
      ->capture_default_str();
  command
      ->add_option("--max-connections", options->max_connections,
                   "Connections served at once; beyond, a newcomer takes the slot of one that awaits its "
                   "request, or one of 4 kept for /api/health, or is answered 503")
      ->check(CLI::Range(1, 10000))
      ->capture_default_str();
  command
      ->add_option("--max-connections-per-client", options->max_connections_per_client,
                   "Of them, the most one client address holds [default: half of --max-connections]")
      ->check(CLI::Range(1, 10000));
  command->add_flag("--quiet", options->quiet, "No access log (one line per request on stderr)");
  command->callback([options, &exit_code] {
    try {
      exit_code = serve(*options);
    } catch (const std::exception& error) {
      std::cerr << "aerobreak serve: " << error.what() << "\n";
      exit_code = kExitError;
    }
  });
}

}  // namespace aerobreak
