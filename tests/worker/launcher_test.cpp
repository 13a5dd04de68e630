// The command lines of worker jobs (orchestrator/scheduler/launcher.hpp) and how a job is ended
// (worker_job.hpp). That the srun line runs, and ends, under a real Slurm is checked by
// tests/slurm/run_slurm_study.sh (docs/ORCHESTRATOR.md, "Slurm").
#include <catch2/catch.hpp>
#include <signal.h>

#include <chrono>
#include <fstream>
#include <string>
#include <thread>

#include "orchestrator/scheduler/launcher.hpp"
#include "orchestrator/scheduler/worker_job.hpp"
#include "tests/support/scratch_directory.hpp"

using namespace aerobreak;

TEST_CASE("Worker job command lines: mpirun, srun with PMIx, stdin to task 0 and kill on bad exit, direct") {
  LauncherConfig config{"mpirun", 4, {"--hostfile", "hosts"}, "/opt/aerobreak"};
  CHECK(join_command(worker_job_command(config)) == "mpirun -np 4 --hostfile hosts /opt/aerobreak worker");
  config.kind = "srun";
  config.arguments = {"--mpi=pmi2"};
  // The launcher's own arguments come after aerobreak's, so that a site can override them.
  CHECK(join_command(worker_job_command(config)) ==
        "srun --ntasks=4 --input=0 --mpi=pmix --kill-on-bad-exit=1 --mpi=pmi2 /opt/aerobreak worker");
  config.silence_limit = 2.5;
  CHECK(join_command(worker_job_command(config)) ==
        "srun --ntasks=4 --input=0 --mpi=pmix --kill-on-bad-exit=1 --mpi=pmi2 /opt/aerobreak worker "
        "--silence-limit 2.5");
  config = {"direct", 1, {}, "/opt/aerobreak"};
  CHECK(join_command(worker_job_command(config)) == "/opt/aerobreak worker");
  config.ranks = 2;
  CHECK_THROWS_AS(worker_job_command(config), std::invalid_argument);
  config = {"pbs", 1, {}, "/opt/aerobreak"};
  CHECK_THROWS_AS(worker_job_command(config), std::invalid_argument);
}

TEST_CASE("A worker job is ended with SIGTERM first, so that its launcher can end its ranks and Slurm job") {
  const aerobreak::testing::ScratchDirectory directory("worker_job_end");
  const auto marker = directory.path() / "terminated";
  // A launcher that, like srun and mpirun, cleans up on SIGTERM.
  WorkerJob polite({"/bin/sh", "-c",
                    "trap 'echo cleaned up > " + marker.string() +
                        "; exit 0' TERM; "
                        "while :; do sleep 0.05; done"},
                   directory.path() / "polite.log");
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // the trap is set
  polite.kill();
  CHECK(polite.exit_status() == 0);
  std::ifstream in(marker);
  std::string text;
  std::getline(in, text);
  CHECK(text == "cleaned up");

  // One that ignores SIGTERM gets SIGKILL after the grace period.
  WorkerJob stubborn({"/bin/sh", "-c", "trap '' TERM; while :; do sleep 0.05; done"},
                     directory.path() / "stubborn.log");
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  const auto start = std::chrono::steady_clock::now();
  stubborn.kill();
  const auto waited = std::chrono::steady_clock::now() - start;
  CHECK(stubborn.exit_status() == 128 + SIGKILL);
  CHECK(waited >= WorkerJob::kTerminationGrace);
  CHECK(waited < WorkerJob::kTerminationGrace + std::chrono::seconds(5));
}
