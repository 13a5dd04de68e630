#pragma once
#include <CLI/CLI.hpp>

namespace aerobreak {

// `aerobreak serve`: the orchestrator as a service. Opens (or creates) the store, recovers what an
// earlier orchestrator left running, schedules queued cases onto worker jobs and serves the REST
// API (schemas/openapi.json) until SIGINT or SIGTERM. Exit status 0 after a signal, 1 when it
// cannot start (store, address, token).
void add_serve_command(CLI::App& app, int& exit_code);

}  // namespace aerobreak
