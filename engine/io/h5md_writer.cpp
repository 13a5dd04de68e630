#include "engine/io/h5md_writer.hpp"

#include <map>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "engine/io/hdf5_attributes.hpp"
#include "engine/io/hdf5_datasets.hpp"
#include "engine/io/hdf5_handle.hpp"

namespace aerobreak {

static_assert(sizeof(Vec3) == 3 * sizeof(double) && std::is_standard_layout_v<Vec3>,
              "Vec3 arrays are written to HDF5 as contiguous [N][3] doubles");

namespace {

constexpr hsize_t dimension = 3;

// An H5MD time-dependent element (H5MD 1.1, "Time-dependent data", explicit step and time
// storage): a group holding `step` (Integer[variable]), `time` (Float[variable]) and `value`
// ([variable][...]). An element sampled together with another one hard-links that element's `step`
// and `time` datasets instead of holding its own; its `step` and `time` handles stay empty.
struct TimeDependentElement {
  Hdf5Handle group;
  Hdf5Handle step;
  Hdf5Handle time;
  Hdf5Handle value;
  std::optional<std::int64_t> last_step;
};

TimeDependentElement create_element(hid_t parent, const std::string& name, const std::vector<hsize_t>& row_shape) {
  TimeDependentElement element;
  element.group = create_group(parent, name);
  element.step = create_extendable_dataset(element.group.get(), "step", H5T_STD_I64LE, {});
  element.time = create_extendable_dataset(element.group.get(), "time", H5T_IEEE_F64LE, {});
  element.value = create_extendable_dataset(element.group.get(), "value", H5T_IEEE_F64LE, row_shape);
  return element;
}

TimeDependentElement create_element_sampled_with(const TimeDependentElement& clock, hid_t parent,
                                                 const std::string& name, const std::vector<hsize_t>& row_shape) {
  TimeDependentElement element;
  element.group = create_group(parent, name);
  create_hard_link(clock.step.get(), element.group.get(), "step");
  create_hard_link(clock.time.get(), element.group.get(), "time");
  element.value = create_extendable_dataset(element.group.get(), "value", H5T_IEEE_F64LE, row_shape);
  return element;
}

void check_step_increases(const TimeDependentElement& element, std::int64_t step, const std::string& what) {
  // H5MD 1.1: the values of `step` are "in monotonically increasing order".
  if (element.last_step && step <= *element.last_step)
    throw std::invalid_argument(what + ": step " + std::to_string(step) + " does not follow step " +
                                std::to_string(*element.last_step));
}

void append_step_and_time(TimeDependentElement& element, std::int64_t step, double time) {
  append_row(element.step.get(), H5T_NATIVE_INT64, &step);
  append_row(element.time.get(), H5T_NATIVE_DOUBLE, &time);
  element.last_step = step;
}

void write_h5md_metadata(hid_t file, std::string_view creator_version, const std::string& author) {
  // H5MD 1.1, "H5MD metadata": h5md/version, h5md/author/name, h5md/creator/{name,version}.
  const Hdf5Handle h5md = create_group(file, "h5md");
  write_integer_array_attribute(h5md.get(), "version", {1, 1});
  write_string_attribute(create_group(h5md.get(), "author").get(), "name", author);
  const Hdf5Handle creator = create_group(h5md.get(), "creator");
  write_string_attribute(creator.get(), "name", "aerobreak");
  write_string_attribute(creator.get(), "version", creator_version);
}

void write_open_box(hid_t particle_group) {
  // H5MD 1.1, "Simulation box": `dimension` and `boundary` attributes. An impact has no periodic
  // direction, so every boundary is "none", and then "edges may be omitted".
  const Hdf5Handle box = create_group(particle_group, "box");
  write_integer_attribute(box.get(), "dimension", static_cast<std::int32_t>(dimension));
  write_string_array_attribute(box.get(), "boundary", {"none", "none", "none"});
}

void write_particle_ids(hid_t particle_group, std::size_t count) {
  // H5MD 1.1, "Particles group", `id`: a time-independent Integer[N] dataset.
  std::vector<std::int64_t> ids(count);
  std::iota(ids.begin(), ids.end(), std::int64_t{0});
  write_dataset(particle_group, "id", H5T_STD_I64LE, H5T_NATIVE_INT64, {count}, ids.data());
}

bool is_link_name(const std::string& name) {
  return !name.empty() && name != "." && name.find('/') == std::string::npos;
}

}  // namespace

struct H5mdTrajectoryWriter::State {
  std::string path;
  H5mdWriterOptions options;
  Hdf5Handle file;
  Hdf5Handle particle_group;
  Hdf5Handle observable_group;
  std::size_t particle_count = 0;
  std::size_t frames = 0;
  TimeDependentElement position;
  TimeDependentElement velocity;
  TimeDependentElement force;
  TimeDependentElement radius;
  std::map<std::string, TimeDependentElement> observables;

  void require_open(const char* operation) const {
    if (!file.valid())
      throw std::logic_error("H5mdTrajectoryWriter::" + std::string(operation) + " after close: " + path);
  }

  void check_frame(const Particles& particles, std::int64_t step) const {
    const std::size_t n = particles.size();
    if (n == 0) throw std::invalid_argument("H5MD frame without particles: " + path);
    if (frames > 0 && n != particle_count)
      throw std::invalid_argument("H5MD frame has " + std::to_string(n) + " particles but " + path + " holds " +
                                  std::to_string(particle_count) + " per frame");
    const bool consistent = particles.radius.size() == n && (!options.velocities || particles.velocity.size() == n) &&
                            (!options.forces || particles.force.size() == n);
    if (!consistent) throw std::invalid_argument("H5MD frame: particle arrays differ in length: " + path);
    check_step_increases(position, step, "H5MD frame for " + path);
  }

  // The particle elements, created with the first frame, once N is known.
  void create_particle_elements(std::size_t n) {
    particle_count = n;
    const hid_t group = particle_group.get();
    position = create_element(group, "position", {n, dimension});
    if (options.velocities) velocity = create_element_sampled_with(position, group, "velocity", {n, dimension});
    if (options.forces) force = create_element_sampled_with(position, group, "force", {n, dimension});
    radius = create_element_sampled_with(position, group, "radius", {n});
    write_particle_ids(group, n);
  }

  void flush() const { check_status(H5Fflush(file.get(), H5F_SCOPE_LOCAL), "flush", path); }
};

H5mdTrajectoryWriter::H5mdTrajectoryWriter(const std::filesystem::path& path, std::string_view creator_version,
                                           const H5mdWriterOptions& options)
    : state_(std::make_unique<State>()) {
  const Hdf5ErrorSilencer silencer;
  State& s = *state_;
  s.path = path.string();
  s.options = options;

  // H5MD 1.1, "File format": HDF5 file format version 2 is recommended; it needs the 1.8 format.
  const Hdf5Handle access = checked_handle(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "create file access list", s.path);
  check_status(H5Pset_libver_bounds(access.get(), H5F_LIBVER_V18, H5F_LIBVER_V18), "select file format", s.path);
  s.file = checked_handle(H5Fcreate(s.path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get()), H5Fclose, "create file",
                          s.path);

  write_h5md_metadata(s.file.get(), creator_version, options.author);
  const Hdf5Handle particles = create_group(s.file.get(), "particles");
  s.particle_group = create_group(particles.get(), "all");
  write_open_box(s.particle_group.get());
  s.flush();
}

H5mdTrajectoryWriter::H5mdTrajectoryWriter(H5mdTrajectoryWriter&&) noexcept = default;
H5mdTrajectoryWriter& H5mdTrajectoryWriter::operator=(H5mdTrajectoryWriter&&) noexcept = default;

H5mdTrajectoryWriter::~H5mdTrajectoryWriter() {
  try {
    close();
  } catch (const std::exception&) {
    // A destructor must not throw; call close() explicitly to see a failure to finish the file.
  }
}

void H5mdTrajectoryWriter::append(const Particles& particles, std::int64_t step, double time) {
  if (!state_) throw std::logic_error("H5mdTrajectoryWriter::append on a moved-from writer");
  State& s = *state_;
  s.require_open("append");
  s.check_frame(particles, step);

  const Hdf5ErrorSilencer silencer;
  if (s.frames == 0) s.create_particle_elements(particles.size());
  append_row(s.position.value.get(), H5T_NATIVE_DOUBLE, particles.position.data());
  if (s.options.velocities) append_row(s.velocity.value.get(), H5T_NATIVE_DOUBLE, particles.velocity.data());
  if (s.options.forces) append_row(s.force.value.get(), H5T_NATIVE_DOUBLE, particles.force.data());
  append_row(s.radius.value.get(), H5T_NATIVE_DOUBLE, particles.radius.data());
  append_step_and_time(s.position, step, time);
  ++s.frames;
  s.flush();
}

void H5mdTrajectoryWriter::append_observable(const std::string& name, std::int64_t step, double time, double value) {
  if (!state_) throw std::logic_error("H5mdTrajectoryWriter::append_observable on a moved-from writer");
  State& s = *state_;
  s.require_open("append_observable");
  if (!is_link_name(name)) throw std::invalid_argument("H5MD observable name '" + name + "' is not a valid group name");

  const Hdf5ErrorSilencer silencer;
  // H5MD 1.1, "Observables group": each observable is a time-dependent element of shape [variable].
  if (!s.observable_group.valid()) s.observable_group = create_group(s.file.get(), "observables");
  auto found = s.observables.find(name);
  if (found == s.observables.end())
    found = s.observables.emplace(name, create_element(s.observable_group.get(), name, {})).first;
  TimeDependentElement& observable = found->second;
  check_step_increases(observable, step, "H5MD observable " + name + " in " + s.path);
  append_row(observable.value.get(), H5T_NATIVE_DOUBLE, &value);
  append_step_and_time(observable, step, time);
  s.flush();
}

std::size_t H5mdTrajectoryWriter::frame_count() const { return state_ ? state_->frames : 0; }

void H5mdTrajectoryWriter::close() {
  if (!state_ || !state_->file.valid()) return;
  const Hdf5ErrorSilencer silencer;
  State& s = *state_;
  s.observables.clear();
  s.position = {};
  s.velocity = {};
  s.force = {};
  s.radius = {};
  s.observable_group.close();
  s.particle_group.close();
  check_status(s.file.close(), "close file", s.path);
}

}  // namespace aerobreak
