#include "orchestrator/scheduler/launcher.hpp"

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
    command = {"srun", "--ntasks=" + std::to_string(config.ranks), "--input=0"};
  } else if (config.kind == "direct") {
    if (config.ranks != 1) throw std::invalid_argument("the direct launcher runs exactly one rank");
  } else {
    throw std::invalid_argument("unknown launcher '" + config.kind + "' (mpirun, srun or direct)");
  }
  command.insert(command.end(), config.arguments.begin(), config.arguments.end());
  command.push_back(config.program.string());
  command.push_back("worker");
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
