#pragma once
#include <CLI/CLI.hpp>

namespace aerobreak {

// `aerobreak impact CASE.json`: runs one impact case (schemas/case.schema.json) and writes its
// result (schemas/result.schema.json); optionally an H5MD and/or XYZ trajectory. Exit status 0 for
// a completed run (whatever its outcome, "undetermined" included), 1 for an invalid case, 3 for a
// run that failed. Progress goes to stderr.
void add_impact_command(CLI::App& app, int& exit_code);

}  // namespace aerobreak
