#pragma once
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

#include "engine/core/vec3.hpp"

namespace aerobreak {

// One frame of the particle group particles/all of an H5MD 1.x file.
struct H5mdFrame {
  std::int64_t step = 0;
  std::optional<double> time;  // absent if the position element stores no time
  std::vector<Vec3> position;
  std::vector<Vec3> velocity;  // empty if the file holds no velocity for this step
  std::vector<Vec3> force;     // empty if the file holds no force for this step
  std::vector<double> radius;  // empty if the file holds no radius for this step
};

// The number of frames of particles/all/position. Throws std::runtime_error if the file cannot
// be read or is not H5MD 1.x.
std::size_t h5md_frame_count(const std::filesystem::path& path);

// Frame `frame_index` (zero-based, in file order) of particles/all. velocity, force and radius are
// taken from the rows sampled at the same step as the position, or from time-independent datasets.
// Throws std::out_of_range for a frame index past the end, std::runtime_error if the file cannot
// be read, is not H5MD 1.x, or holds elements of unexpected shape.
H5mdFrame read_h5md_frame(const std::filesystem::path& path, std::size_t frame_index);

}  // namespace aerobreak
