#include "orchestrator/worker/case_data_file.hpp"

#include <hdf5.h>

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstring>
#include <stdexcept>
#include <system_error>

#include "engine/core/version.hpp"
#include "engine/dem/simulation.hpp"
#include "engine/impact/fragments.hpp"
#include "engine/io/hdf5_datasets.hpp"
#include "engine/io/hdf5_handle.hpp"

namespace aerobreak {
namespace {

// "<path>.<host>.<pid>.<n>.partial": a name of this writer's own. An attempt whose rank was given
// up (stopped, or its node cut off) may still hold its file open, with HDF5's lock on it; the
// case's next attempt, on another rank, must not need that name (seen with a rank stopped by
// SIGSTOP: the re-run failed on the lock, as a storage fault, for as long as the rank stayed
// stopped: tests/slurm/run_slurm_cluster.sh).
std::filesystem::path partial_path_of(const std::filesystem::path& path) {
  static std::atomic<unsigned> writers{0};
  char host[256] = {};
  if (::gethostname(host, sizeof host - 1) != 0) std::strcpy(host, "host");
  std::filesystem::path partial = path;
  partial += "." + std::string(host) + "." + std::to_string(::getpid()) + "." + std::to_string(writers++) + ".partial";
  return partial;
}

// Runs a step that writes the file, turning its failure (HDF5, file system) into DataFileError.
template <typename Step>
void writing(const std::filesystem::path& path, Step step) {
  try {
    step();
  } catch (const std::exception& error) {
    std::string reason = error.what();  // HDF5's spans lines; the protocol and the logs take one
    std::replace(reason.begin(), reason.end(), '\n', ' ');
    throw DataFileError("cannot write the data file " + path.string() + ": " + reason);
  }
}

}  // namespace

CaseDataFile::CaseDataFile(std::filesystem::path path) : path_(std::move(path)), partial_(partial_path_of(path_)) {
  writing(path_, [this] {
    if (path_.has_parent_path()) std::filesystem::create_directories(path_.parent_path());
    writer_.emplace(partial_, version());
  });
}

CaseDataFile::~CaseDataFile() {
  if (committed_) return;
  writer_.reset();
  std::error_code ignored;
  std::filesystem::remove(partial_, ignored);
}

void CaseDataFile::record(const Simulation& simulation) {
  if (!first_step_) {
    writing(path_, [&] { writer_->append(simulation.particles(), simulation.step_count(), simulation.time()); });
    first_step_ = simulation.step_count();
  }
  // The run does not say which snapshot is its last: keep each until the next replaces it. The
  // fragments cost one pass over the contacts, about as much as the copy of the particles.
  latest_ =
      State{simulation.particles(), simulation.step_count(), simulation.time(), find_fragments(simulation).fragment_of};
}

void CaseDataFile::commit() {
  if (!latest_) throw std::logic_error("case data file " + path_.string() + ": no state was recorded");
  writing(path_, [this] {
    if (latest_->step != *first_step_) writer_->append(latest_->particles, latest_->step, latest_->time);
    writer_->close();
    write_fragments(*latest_);
    std::filesystem::rename(partial_, path_);
  });
  committed_ = true;
}

void CaseDataFile::write_fragments(const State& state) const {
  // An H5MD time-dependent element (H5MD 1.1, "Time-dependent data") of its own, sampled once:
  // the writer's elements all share the position's steps.
  const Hdf5ErrorSilencer silencer;
  const std::string name = partial_.string();
  Hdf5Handle file = checked_handle(H5Fopen(name.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose, "open file", name);
  {
    const Hdf5Handle particles = open_group(file.get(), "particles/all");
    const Hdf5Handle element = create_group(particles.get(), "fragment");
    const Hdf5Handle step = create_extendable_dataset(element.get(), "step", H5T_STD_I64LE, {});
    append_row(step.get(), H5T_NATIVE_INT64, &state.step);
    const Hdf5Handle time = create_extendable_dataset(element.get(), "time", H5T_IEEE_F64LE, {});
    append_row(time.get(), H5T_NATIVE_DOUBLE, &state.time);
    const Hdf5Handle value =
        create_extendable_dataset(element.get(), "value", H5T_STD_I32LE, {state.fragment_of.size()});
    append_row(value.get(), H5T_NATIVE_UINT32, state.fragment_of.data());
  }
  check_status(file.close(), "close file", name);
}

}  // namespace aerobreak
