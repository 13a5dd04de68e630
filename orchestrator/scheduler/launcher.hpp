#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace aerobreak {

// How the orchestrator starts a worker job (`aerobreak worker`, docs/WORKER_PROTOCOL.md). The job
// reads cases on the launcher's stdin, which must reach rank 0.
//   mpirun  Open MPI: mpirun -np RANKS [ARGS...] AEROBREAK worker. With one rank it runs on a
//           laptop; with --hostfile FILE in ARGS it spans machines.
//   srun    Slurm: srun --ntasks=RANKS --input=0 --mpi=pmix --kill-on-bad-exit=1 [ARGS...] AEROBREAK
//           worker, inside an allocation or making one (--input=0: stdin to task 0 only; --mpi=pmix:
//           the ranks find each other through Slurm's PMIx, as Open MPI needs when srun starts
//           them; --kill-on-bad-exit=1: a task that dies ends the step, instead of leaving the
//           others waiting for it in MPI_Init).
//   direct  AEROBREAK worker as a single process (an MPI singleton; no launcher needed).
struct LauncherConfig {
  std::string kind = "mpirun";
  int ranks = 1;
  std::vector<std::string> arguments;  // passed to the launcher before the program
  std::filesystem::path program;       // the aerobreak executable the ranks run
  double silence_limit = 0.0;          // seconds; > 0: passed on as `worker --silence-limit`
};

// The launcher kinds, as the CLI lists them.
const std::vector<std::string>& launcher_kinds();

// The command line of a worker job; throws std::invalid_argument for an unknown kind or ranks < 1.
std::vector<std::string> worker_job_command(const LauncherConfig& config);

// The command line as one printable string (for logs and the jobs table).
std::string join_command(const std::vector<std::string>& command);

// The path of the running executable (/proc/self/exe), so that workers run the same build.
std::filesystem::path current_executable();

}  // namespace aerobreak
