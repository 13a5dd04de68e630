// aerobreak: one command-line program; each job is a subcommand.
#include <CLI/CLI.hpp>

#include <iostream>
#include <string>

#include "engine/core/version.hpp"
#include "orchestrator/cli/bench_command.hpp"
#include "orchestrator/cli/impact_command.hpp"
#include "orchestrator/cli/cluster_command.hpp"
#include "orchestrator/cli/exit_codes.hpp"
#include "orchestrator/cli/export_command.hpp"
#include "orchestrator/cli/run_command.hpp"
#include "orchestrator/cli/serve_command.hpp"
#include "orchestrator/cli/study_client_command.hpp"
#include "orchestrator/cli/study_expand_command.hpp"
#include "orchestrator/cli/worker_command.hpp"

namespace {

constexpr const char* kAbout =
    "aerobreak simulates fractal aerosol clusters (e.g. 20 nm ammonium-nitrate spheres held together\n"
    "by surface adhesion) hitting a wall with a discrete-element engine (JKR adhesion, visco-elastic\n"
    "damping, Mindlin friction, rolling and twisting resistance), classifies each impact as stick,\n"
    "bounce or break-up with its fragment-size distribution, and turns sweeps of impacts into\n"
    "correlation tables for system-level aerosol codes.";

// CLI11 prints the message; every command-line error (an unknown option, a missing argument, a
// file it names that does not exist) ends with one status, not CLI11's 100-114.
int exit_status(const CLI::App& app, const CLI::ParseError& error) {
  const int cli11_status = app.exit(error);
  if (dynamic_cast<const CLI::RuntimeError*>(&error) || cli11_status == 0) return cli11_status;
  return aerobreak::kExitInvalidInput;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{kAbout, "aerobreak"};
  app.footer("Run 'aerobreak SUBCOMMAND --help' for the options of each subcommand.\n");
  app.set_version_flag(
      "--version",
      [] {
        return "aerobreak " + std::string(aerobreak::version()) + " (commit " + std::string(aerobreak::git_commit()) +
               ")";
      },
      "Print the version and the git commit this binary was built from");

  int exit_code = 0;
  aerobreak::add_run_command(app, exit_code);
  aerobreak::add_serve_command(app, exit_code);
  auto* study =
      app.add_subcommand("study", "Submit, inspect or cancel studies on a running service; expand a study offline");
  study->require_subcommand(1);
  aerobreak::add_study_client_subcommands(*study, exit_code);
  aerobreak::add_study_expand_subcommand(*study);
  aerobreak::add_export_command(app, exit_code);
  aerobreak::add_impact_command(app, exit_code);
  aerobreak::add_cluster_command(app);
  aerobreak::add_bench_command(app);
  aerobreak::add_worker_command(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return exit_status(app, e);
  }
  if (argc == 1) {
    std::cout << app.help();
  }
  return exit_code;
}
