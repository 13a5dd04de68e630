#pragma once
#include <CLI/CLI.hpp>

namespace aerobreak {

// `aerobreak bench`: particle-steps per second of a relaxed fractal cluster hitting a wall with
// the full contact model, for several cluster sizes.
void add_bench_command(CLI::App& app);

}  // namespace aerobreak
