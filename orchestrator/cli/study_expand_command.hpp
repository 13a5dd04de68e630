#pragma once
#include <CLI/CLI.hpp>

namespace aerobreak {

// `aerobreak study expand STUDY.json [--json]`: checks a study file (schemas/study.schema.json) and
// lists its cases offline (count, then index, hash prefix, grid point and replicate per case), or
// with --json prints them as a JSON array of {hash, grid_point, replicate, document}. An invalid
// study lists each violation on stderr and exits with status 2.
void add_study_expand_subcommand(CLI::App& study);

}  // namespace aerobreak
