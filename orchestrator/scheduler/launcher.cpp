#include "orchestrator/scheduler/launcher.hpp"

#include <cstdio>
#include <stdexcept>

namespace aerobreak {

const std::vector<std::string>& launcher_kinds() {
  static const std::vector<std::string> kinds{"mpirun", "srun", "direct"};
  return kinds;
}

std::vector<std::string> worker_job_command(const LauncherConfig& config) {
  if (config.ranks < 1) throw std::invalid_argument("a worker job needs at least one rank");
  std::vector<std::string> command;
  if (config.kind == "mpirun") {
    command = {"mpirun", "-np", std::to_string(config.ranks)};
  } else if (config.kind == "srun") {
    // Tasks that srun starts itself find each other through Slurm's PMIx plugin, which Debian's
    // Open MPI needs (without it every task fails in MPI_Init: "OMPI was not built with SLURM's
    // PMI support"); tests/slurm/run_slurm_study.sh ran it against a real Slurm. A site whose
    // Open MPI wants PMI-2 overrides it: --launcher-arg=--mpi=pmi2 (the later option wins).
    // Without --kill-on-bad-exit a task that dies while the job starts (seen on a node back from a
    // failure, tests/slurm/run_slurm_cluster.sh) leaves the others waiting in MPI_Init for ever;
    // with it srun ends the step and the orchestrator launches the job again.
    command = {"srun", "--ntasks=" + std::to_string(config.ranks), "--input=0", "--mpi=pmix", "--kill-on-bad-exit=1"};
  } else if (config.kind == "direct") {
    if (config.ranks != 1) throw std::invalid_argument("the direct launcher runs exactly one rank");
  } else {
    throw std::invalid_argument("unknown launcher '" + config.kind + "' (mpirun, srun or direct)");
  }
  command.insert(command.end(), config.arguments.begin(), config.arguments.end());
  command.push_back(config.program.string());
  command.push_back("worker");
  if (config.silence_limit > 0.0) {
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%g", config.silence_limit);
    command.insert(command.end(), {"--silence-limit", seconds});
  }
  return command;
}

std::string join_command(const std::vector<std::string>& command) {
  std::string joined;
  for (const auto& word : command) {
    if (!joined.empty()) joined += ' ';
    const bool plain = !word.empty() && word.find_first_of(" \t'\"\\$") == std::string::npos;
    joined += plain ? word : "'" + word + "'";
  }
  return joined;
}

std::filesystem::path current_executable() { return std::filesystem::read_symlink("/proc/self/exe"); }

}  // namespace aerobreak
