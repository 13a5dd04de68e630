#pragma once
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <vector>

#include "engine/core/particles.hpp"
#include "engine/io/h5md_writer.hpp"

namespace aerobreak {

class Simulation;

// The data file could not be created, written or renamed (disk full, no permission, I/O error).
class DataFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The bulk arrays of one case (docs/ARCHITECTURE.md: the store references HDF5 files for them), as an H5MD
// file (engine/io/h5md_writer.hpp) with two frames, the state when the impact starts and when it
// ends (one frame if the run took no step), plus each primary's fragment at the end:
//
//   particles/all/fragment    step [1], time [1], value [1][N] (int32, the index into the result's
//                             /fragments list, largest first; sampled at the last frame only)
//
// The file is written under a name of its own beside `path`, "<path>.<host>.<pid>.<n>.partial"
// (parent directories created), and renamed to `path` by commit(), so that `path` only ever names
// a complete file and two attempts at one case never write the same file; an uncommitted file is
// removed. Every failure to create, write or rename it throws DataFileError.
class CaseDataFile {
 public:
  explicit CaseDataFile(std::filesystem::path path);
  CaseDataFile(const CaseDataFile&) = delete;
  CaseDataFile& operator=(const CaseDataFile&) = delete;
  ~CaseDataFile();

  // For every snapshot of the run: the first is written at once, the latest is kept for commit().
  void record(const Simulation& simulation);

  // Writes the last state and its fragments, closes the file and gives it its name.
  void commit();

  const std::filesystem::path& path() const { return path_; }

 private:
  struct State {
    Particles particles;
    std::int64_t step = 0;
    double time = 0.0;
    std::vector<std::uint32_t> fragment_of;
  };

  void write_fragments(const State& state) const;

  std::filesystem::path path_;
  std::filesystem::path partial_;
  std::optional<H5mdTrajectoryWriter> writer_;
  std::optional<std::int64_t> first_step_;
  std::optional<State> latest_;
  bool committed_ = false;
};

}  // namespace aerobreak
