#include "orchestrator/cli/worker_command.hpp"

#include "orchestrator/worker/mpi_worker.hpp"

namespace aerobreak {

void add_worker_command(CLI::App& app) {
  auto* worker = app.add_subcommand(
      "worker",
      "Run as a worker job under mpirun/srun for the orchestrator (reads cases on stdin; see docs/WORKER_PROTOCOL.md)");
  worker->callback([] { run_worker_job(); });
}

}  // namespace aerobreak
