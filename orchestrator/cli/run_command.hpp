#pragma once
#include <CLI/CLI.hpp>

namespace aerobreak {

// `aerobreak run STUDY.json`: runs a study (schemas/study.schema.json) to completion on this
// machine: the store is a local SQLite file, worker jobs start through the launcher (mpirun by
// default), the REST service answers on loopback while it runs; a progress bar on stderr, the
// outcome table on stdout. Rerunning the same command resumes an interrupted run; finished cases
// are never rerun. Exit status 0 when every case finished, 1 for an invalid study or a start-up
// failure, 3 when some cases failed, 130 when interrupted.
void add_run_command(CLI::App& app, int& exit_code);

}  // namespace aerobreak
