#pragma once
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

#include "engine/core/particles.hpp"

namespace aerobreak {

struct H5mdWriterOptions {
  bool velocities = true;
  bool forces = false;
  std::string author = "unknown";  // h5md/author/name, the person responsible for the run
};

// Writes a particle trajectory in the H5MD 1.1 layout (de Buyl, Colberg and Hoefling, Comput.
// Phys. Commun. 185 (2014) 1546; https://www.nongnu.org/h5md/), readable by OVITO, MDAnalysis and
// other H5MD tools:
//
//   h5md                      version = [1, 1]; author/name; creator/name, creator/version
//   particles/all/box         dimension = 3, boundary = [none, none, none] (no periodicity)
//   particles/all/position    step [frames], time [frames], value [frames][N][3]
//   particles/all/velocity    value [frames][N][3] (optional; step, time hard-linked to position's)
//   particles/all/force       value [frames][N][3] (optional; idem)
//   particles/all/radius      value [frames][N]    (custom element; idem)
//   particles/all/id          [N], particle index (time-independent)
//   observables/NAME          step, time, value [samples]
//
// The particle count N is fixed by the first frame. The file is created (truncating an existing
// one) by the constructor and complete after close() or destruction; every frame is flushed to
// disk as it is appended, so a run that dies leaves a readable file. HDF5 failures throw
// std::runtime_error naming the file.
class H5mdTrajectoryWriter {
 public:
  H5mdTrajectoryWriter(const std::filesystem::path& path, std::string_view creator_version,
                       const H5mdWriterOptions& options = {});
  H5mdTrajectoryWriter(H5mdTrajectoryWriter&&) noexcept;
  H5mdTrajectoryWriter& operator=(H5mdTrajectoryWriter&&) noexcept;
  ~H5mdTrajectoryWriter();

  // Appends one frame. Throws std::invalid_argument if the particle count differs from the first
  // frame's or is zero, if the particle arrays disagree in length, or if `step` does not increase.
  void append(const Particles& particles, std::int64_t step, double time);

  // Appends one sample of the scalar observable observables/NAME (created on first use). `name`
  // must be a single, non-empty HDF5 link name (no '/'); its steps must increase.
  void append_observable(const std::string& name, std::int64_t step, double time, double value);

  std::size_t frame_count() const;

  // Closes every HDF5 object and the file; further appends throw std::logic_error. Idempotent.
  void close();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace aerobreak
