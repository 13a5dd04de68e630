#pragma once
#include <CLI/CLI.hpp>

namespace aerobreak {

// `aerobreak cluster generate|analyze|convert`: builds relaxed fractal clusters into a cluster
// library (engine/io/cluster_library.hpp) or an XYZ file, prints their structure, and converts
// between the two formats. A failure is reported on stderr and ends the program with status 1.
void add_cluster_command(CLI::App& app);

}  // namespace aerobreak
