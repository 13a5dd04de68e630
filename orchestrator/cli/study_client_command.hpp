#pragma once
#include <CLI/CLI.hpp>

namespace aerobreak {

// `aerobreak study submit|list|status|results|cancel`: a client of a running service's REST API
// (--url, or AEROBREAK_URL, default http://127.0.0.1:8080; --token-file or AEROBREAK_TOKEN for
// services that require a token). Exit status 0 on success, 2 when the service refused the request
// (its error and every named field printed), 3 when the service cannot be reached.
void add_study_client_subcommands(CLI::App& study, int& exit_code);

}  // namespace aerobreak
