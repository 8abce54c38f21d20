#pragma once
// Small helpers over HDF5's C API for the checkpoint files: an owner for each identifier, so
// that nothing stays open when an exception leaves a function, and the error stack turned
// into text for the exceptions partimix throws (HDF5 itself prints nothing).
#include <hdf5.h>

#include <string>

namespace partimix::io {

// Owns one HDF5 identifier (file, group, dataset, dataspace, datatype, attribute, property
// list) and closes it with the matching H5?close. Move-only.
class Hdf5Handle {
 public:
  using Closer = herr_t (*)(hid_t);

  Hdf5Handle() = default;
  Hdf5Handle(hid_t id, Closer closer) : id_(id), closer_(closer) {}
  ~Hdf5Handle() { close(); }
  Hdf5Handle(Hdf5Handle&& other) noexcept;
  Hdf5Handle& operator=(Hdf5Handle&& other) noexcept;
  Hdf5Handle(const Hdf5Handle&) = delete;
  Hdf5Handle& operator=(const Hdf5Handle&) = delete;

  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }
  // Closes now; false when HDF5 reports a failure (for a file, the last writes happen here).
  bool close();

 private:
  hid_t id_ = H5I_INVALID_HID;
  Closer closer_ = nullptr;
};

// Turns off HDF5's printing of its error stack to stderr. The setting is per thread in a
// thread-safe HDF5 build, so every entry point into the checkpoint code calls this.
void silence_hdf5_errors();

// The innermost message on the calling thread's HDF5 error stack ("truncated file: eof = ...",
// "unable to open file"), or "" when the stack is empty. Read it right after the failing call:
// the next HDF5 call clears the stack.
std::string hdf5_error_detail();

}  // namespace partimix::io
