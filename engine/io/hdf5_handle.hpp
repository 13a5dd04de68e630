#pragma once
#include <hdf5.h>

#include <string>
#include <string_view>

namespace aerobreak {

// Owns one HDF5 identifier (file, group, dataset, dataspace, datatype, attribute, property list)
// and closes it with the matching H5?close function, so that no hid_t outlives its scope.
class Hdf5Handle {
 public:
  using Closer = herr_t (*)(hid_t);

  Hdf5Handle() = default;
  Hdf5Handle(hid_t id, Closer closer) : id_(id), closer_(closer) {}
  Hdf5Handle(const Hdf5Handle&) = delete;
  Hdf5Handle& operator=(const Hdf5Handle&) = delete;
  Hdf5Handle(Hdf5Handle&& other) noexcept;
  Hdf5Handle& operator=(Hdf5Handle&& other) noexcept;
  ~Hdf5Handle() { close(); }

  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }

  // Closes the identifier now; returns the HDF5 status (0 if there was nothing to close).
  herr_t close() noexcept;

 private:
  hid_t id_ = H5I_INVALID_HID;
  Closer closer_ = nullptr;
};

// Turns HDF5's automatic error printing off for its lifetime and restores the previous handler
// afterwards: the I/O code checks every return status itself and reports through exceptions.
class Hdf5ErrorSilencer {
 public:
  Hdf5ErrorSilencer();
  Hdf5ErrorSilencer(const Hdf5ErrorSilencer&) = delete;
  Hdf5ErrorSilencer& operator=(const Hdf5ErrorSilencer&) = delete;
  ~Hdf5ErrorSilencer();

 private:
  H5E_auto2_t previous_function_ = nullptr;
  void* previous_data_ = nullptr;
};

// Throws std::runtime_error "HDF5: <what> (<file>): <most specific message on HDF5's error
// stack>" and clears that stack.
[[noreturn]] void throw_hdf5_error(std::string_view what, const std::string& file);

// The name of the file that holds an open HDF5 object, for error messages.
std::string hdf5_file_name(hid_t object);

// Wraps a freshly returned identifier; throws (see throw_hdf5_error) if it is negative.
Hdf5Handle checked_handle(hid_t id, Hdf5Handle::Closer closer, std::string_view what, const std::string& file);

// Throws (see throw_hdf5_error) if an HDF5 call returned a negative status.
void check_status(herr_t status, std::string_view what, const std::string& file);

}  // namespace aerobreak
