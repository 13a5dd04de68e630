#pragma once
#include <filesystem>
#include <iosfwd>
#include <string_view>

#include "engine/cluster/cluster.hpp"
#include "engine/core/particles.hpp"

namespace aerobreak {

// Plain-text particle coordinates, the format in which users bring their own clusters.
//
// Reading accepts two forms, told apart by the first line:
//  - plain: one particle per line, "x y z" or "x y z radius"; blank lines and lines starting with
//    '#' are skipped; a missing radius is `default_radius` (0.5: unit diameter, reduced units);
//  - XYZ (first line = particle count, second line = comment, then one "species x y z [radius]"
//    line per particle). If the comment line carries an extended-XYZ "Properties=" key (as OVITO
//    and ASE write it), the "pos" and "radius" columns are taken from it.
// Malformed lines, non-finite numbers, radii <= 0 and a particle count that disagrees with the
// count line throw std::runtime_error naming the source, the line number and the line.
Cluster read_xyz_cluster(std::istream& in, double default_radius = 0.5, std::string_view source_name = "XYZ input");
// A file only if it is a regular file of at most kMaxClusterTextBytes (bounded_input.hpp; an
// InputFileError, a std::runtime_error, names it otherwise).
Cluster read_xyz_cluster(const std::filesystem::path& path, double default_radius = 0.5);

// Writes the plain form ("x y z radius" per line after a '#' header) with the shortest decimal
// representation that reads back to the identical double. Throws std::runtime_error if the
// stream or file cannot be written.
void write_xyz_cluster(std::ostream& out, const Cluster& cluster);
void write_xyz_cluster(const std::filesystem::path& path, const Cluster& cluster);

// Appends one frame in extended XYZ form (count line; comment line with "Properties=" so that
// OVITO maps the columns itself, followed by `comment`; "P x y z radius" per particle). Frames
// written one after another form a trajectory. Throws std::invalid_argument if `comment` holds a
// line break, std::runtime_error if the stream cannot be written.
void write_xyz_frame(std::ostream& out, const Particles& particles, std::string_view comment = "");

}  // namespace aerobreak
