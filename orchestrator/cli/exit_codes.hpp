#pragma once

namespace aerobreak {

// The exit status of every subcommand, one meaning each (README, "Exit status").
constexpr int kExitDone = 0;
// The work could not be done: a file, store or port that cannot be used, or any other error.
constexpr int kExitError = 1;
// The input is refused, every problem printed at its field: the command line (an unknown option, a
// missing argument, a file it names that does not exist), a study or case document, the
// parameters of an export, or a document the service refused with a 4xx answer.
constexpr int kExitInvalidInput = 2;
// The simulation ran and failed in part: `run` ended with failed cases, `impact` stopped with an error.
constexpr int kExitPartlyFailed = 3;
// `study` subcommands: no service answers at the URL.
constexpr int kExitUnreachable = 4;
// Stopped by Ctrl-C (SIGINT) or SIGTERM; `run` keeps its finished cases and resumes when run again.
constexpr int kExitInterrupted = 130;

}  // namespace aerobreak
