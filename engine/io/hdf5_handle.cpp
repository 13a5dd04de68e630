#include "engine/io/hdf5_handle.hpp"

#include <stdexcept>
#include <utility>

namespace aerobreak {

Hdf5Handle::Hdf5Handle(Hdf5Handle&& other) noexcept
    : id_(std::exchange(other.id_, H5I_INVALID_HID)), closer_(other.closer_) {}

Hdf5Handle& Hdf5Handle::operator=(Hdf5Handle&& other) noexcept {
  if (this != &other) {
    close();
    id_ = std::exchange(other.id_, H5I_INVALID_HID);
    closer_ = other.closer_;
  }
  return *this;
}

herr_t Hdf5Handle::close() noexcept {
  if (!valid()) return 0;
  const herr_t status = closer_(id_);
  id_ = H5I_INVALID_HID;
  return status;
}

Hdf5ErrorSilencer::Hdf5ErrorSilencer() {
  H5Eget_auto2(H5E_DEFAULT, &previous_function_, &previous_data_);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

Hdf5ErrorSilencer::~Hdf5ErrorSilencer() { H5Eset_auto2(H5E_DEFAULT, previous_function_, previous_data_); }

namespace {

// H5Ewalk2 callback: keeps the description of the first record visited. Walking upward, that is
// the innermost, most specific one (e.g. the operating system's reason a file could not be opened).
herr_t keep_first_description(unsigned position, const H5E_error2_t* record, void* client_data) {
  if (position == 0 && record->desc != nullptr) *static_cast<std::string*>(client_data) = record->desc;
  return 0;
}

}  // namespace

void throw_hdf5_error(std::string_view what, const std::string& file) {
  std::string detail;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, keep_first_description, &detail);
  H5Eclear2(H5E_DEFAULT);
  std::string message = "HDF5: " + std::string(what) + " (" + file + ")";
  if (!detail.empty()) message += ": " + detail;
  throw std::runtime_error(message);
}

std::string hdf5_file_name(hid_t object) {
  const ssize_t length = H5Fget_name(object, nullptr, 0);
  if (length <= 0) return "unknown file";
  std::string name(static_cast<std::size_t>(length) + 1, '\0');
  H5Fget_name(object, name.data(), name.size());
  name.resize(static_cast<std::size_t>(length));
  return name;
}

Hdf5Handle checked_handle(hid_t id, Hdf5Handle::Closer closer, std::string_view what, const std::string& file) {
  if (id < 0) throw_hdf5_error(what, file);
  return Hdf5Handle(id, closer);
}

void check_status(herr_t status, std::string_view what, const std::string& file) {
  if (status < 0) throw_hdf5_error(what, file);
}

}  // namespace aerobreak
