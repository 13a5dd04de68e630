#include "orchestrator/cli/worker_command.hpp"

#include <memory>

#include "orchestrator/worker/mpi_worker.hpp"
#include "orchestrator/worker/worker_protocol.hpp"

namespace aerobreak {

void add_worker_command(CLI::App& app) {
  auto* worker = app.add_subcommand(
      "worker",
      "Run as a worker job under mpirun/srun for the orchestrator (reads cases on stdin; see docs/WORKER_PROTOCOL.md)");
  auto silence_limit = std::make_shared<double>(static_cast<double>(kDefaultSilenceLimit.count()));
  worker
      ->add_option("--silence-limit", *silence_limit,
                   "Seconds a rank running a case may send nothing before it is given up (its case is answered as "
                   "failed, kind lost)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  worker->callback(
      [silence_limit] { run_worker_job(std::chrono::milliseconds(static_cast<long>(*silence_limit * 1000.0))); });
}

}  // namespace aerobreak
