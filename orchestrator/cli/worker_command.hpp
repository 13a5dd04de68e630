#pragma once
#include <CLI/CLI.hpp>

namespace aerobreak {

// `aerobreak worker`: runs as one MPI worker job for the orchestrator (orchestrator/worker/,
// docs/WORKER_PROTOCOL.md). The only subcommand that initialises MPI.
void add_worker_command(CLI::App& app);

}  // namespace aerobreak
