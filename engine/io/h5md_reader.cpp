#include "engine/io/h5md_reader.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "engine/io/hdf5_attributes.hpp"
#include "engine/io/hdf5_datasets.hpp"
#include "engine/io/hdf5_handle.hpp"

namespace aerobreak {

namespace {

struct OpenParticleGroup {
  std::string path;
  Hdf5Handle file;
  Hdf5Handle group;  // particles/all
};

OpenParticleGroup open_particle_group(const std::filesystem::path& path) {
  OpenParticleGroup opened;
  opened.path = path.string();
  opened.file =
      checked_handle(H5Fopen(opened.path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "open file", opened.path);
  // H5MD 1.1, "H5MD metadata": h5md/version holds [major, minor].
  if (!link_exists(opened.file.get(), "h5md"))
    throw std::runtime_error("not an H5MD file (no h5md group): " + opened.path);
  const Hdf5Handle h5md = open_group(opened.file.get(), "h5md");
  const std::vector<std::int64_t> version = read_integer_attribute(h5md.get(), "version");
  if (version.size() != 2 || version[0] != 1)
    throw std::runtime_error("unsupported H5MD version (need 1.x): " + opened.path);
  if (!link_exists(opened.file.get(), "particles/all/position/value"))
    throw std::runtime_error("H5MD file without particles/all/position: " + opened.path);
  opened.group = open_group(opened.file.get(), "particles/all");
  return opened;
}

// The steps of a time-dependent element with `rows` samples, in either storage mode of H5MD 1.1
// ("Explicit step and time storage" or "Fixed step and time storage": s(i) = i * step + offset).
std::vector<std::int64_t> element_steps(hid_t element, hsize_t rows) {
  const Hdf5Handle step = open_dataset(element, "step");
  const std::vector<hsize_t> shape = dataset_shape(step.get());
  std::vector<std::int64_t> steps;
  if (!shape.empty()) {
    steps.resize(shape[0]);
    read_dataset(step.get(), H5T_NATIVE_INT64, steps.data());
    return steps;
  }
  std::int64_t increment = 0;
  read_dataset(step.get(), H5T_NATIVE_INT64, &increment);
  const std::int64_t offset =
      has_attribute(step.get(), "offset") ? read_integer_attribute(step.get(), "offset").at(0) : 0;
  for (hsize_t i = 0; i < rows; ++i) steps.push_back(static_cast<std::int64_t>(i) * increment + offset);
  return steps;
}

// The time of sample `index` of a time-dependent element (same two storage modes as the steps).
std::optional<double> element_time(hid_t element, hsize_t index) {
  if (!link_exists(element, "time")) return std::nullopt;
  const Hdf5Handle time = open_dataset(element, "time");
  double value = 0.0;
  if (!dataset_shape(time.get()).empty()) {
    read_row(time.get(), index, H5T_NATIVE_DOUBLE, &value);
    return value;
  }
  read_dataset(time.get(), H5T_NATIVE_DOUBLE, &value);
  const double offset = has_attribute(time.get(), "offset") ? read_float_attribute(time.get(), "offset").at(0) : 0.0;
  return static_cast<double>(index) * value + offset;
}

void require_shape(bool matches, const std::string& element, const OpenParticleGroup& opened) {
  if (!matches)
    throw std::runtime_error("H5MD element particles/all/" + element + " has an unexpected shape: " + opened.path);
}

// Reads the per-particle data of element `name` at `step` into `out` (N * components doubles),
// from a time-dependent element's row with that step or from a time-independent dataset. Leaves
// `out` empty if the element is absent or was not sampled at `step`.
template <class T>
void read_particle_element(const OpenParticleGroup& opened, const std::string& name, std::int64_t step,
                           std::size_t particle_count, std::vector<T>& out) {
  constexpr hsize_t components = sizeof(T) / sizeof(double);
  const std::vector<hsize_t> per_frame =
      components == 1 ? std::vector<hsize_t>{particle_count} : std::vector<hsize_t>{particle_count, components};
  const hid_t group = opened.group.get();
  if (!link_exists(group, name)) return;

  if (!link_exists(group, name + "/value")) {
    const Hdf5Handle fixed = open_dataset(group, name);
    require_shape(dataset_shape(fixed.get()) == per_frame, name, opened);
    out.resize(particle_count);
    read_dataset(fixed.get(), H5T_NATIVE_DOUBLE, out.data());
    return;
  }

  const Hdf5Handle element = open_group(group, name);
  const Hdf5Handle value = open_dataset(element.get(), "value");
  const std::vector<hsize_t> shape = dataset_shape(value.get());
  require_shape(!shape.empty() && std::vector<hsize_t>(shape.begin() + 1, shape.end()) == per_frame, name, opened);
  const std::vector<std::int64_t> steps = element_steps(element.get(), shape[0]);
  const auto found = std::find(steps.begin(), steps.end(), step);
  if (found == steps.end() || static_cast<hsize_t>(found - steps.begin()) >= shape[0]) return;
  out.resize(particle_count);
  read_row(value.get(), static_cast<hsize_t>(found - steps.begin()), H5T_NATIVE_DOUBLE, out.data());
}

}  // namespace

std::size_t h5md_frame_count(const std::filesystem::path& path) {
  const Hdf5ErrorSilencer silencer;
  const OpenParticleGroup opened = open_particle_group(path);
  const Hdf5Handle value = open_dataset(opened.group.get(), "position/value");
  const std::vector<hsize_t> shape = dataset_shape(value.get());
  require_shape(shape.size() == 3, "position", opened);
  return shape[0];
}

H5mdFrame read_h5md_frame(const std::filesystem::path& path, std::size_t frame_index) {
  const Hdf5ErrorSilencer silencer;
  const OpenParticleGroup opened = open_particle_group(path);
  const Hdf5Handle position = open_group(opened.group.get(), "position");
  const Hdf5Handle value = open_dataset(position.get(), "value");
  const std::vector<hsize_t> shape = dataset_shape(value.get());
  require_shape(shape.size() == 3 && shape[2] == 3, "position", opened);
  if (frame_index >= shape[0])
    throw std::out_of_range("H5MD frame " + std::to_string(frame_index) + " requested but " + opened.path + " holds " +
                            std::to_string(shape[0]));

  H5mdFrame frame;
  const std::vector<std::int64_t> steps = element_steps(position.get(), shape[0]);
  if (steps.size() < shape[0]) throw std::runtime_error("H5MD position has fewer steps than values: " + opened.path);
  frame.step = steps[frame_index];
  frame.time = element_time(position.get(), frame_index);
  const std::size_t particle_count = shape[1];
  frame.position.resize(particle_count);
  read_row(value.get(), frame_index, H5T_NATIVE_DOUBLE, frame.position.data());

  read_particle_element(opened, "velocity", frame.step, particle_count, frame.velocity);
  read_particle_element(opened, "force", frame.step, particle_count, frame.force);
  read_particle_element(opened, "radius", frame.step, particle_count, frame.radius);
  return frame;
}

}  // namespace aerobreak
