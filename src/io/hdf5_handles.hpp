#pragma once
// Owning handles for HDF5 identifiers (hid_t), one alias per kind because each kind has its
// own close function. Move-only; the destructor closes and ignores the status (it may run
// while an exception unwinds). Where a failed close must be reported — the file, whose
// close writes the last metadata — call close() and check what it returns.
//
// Order matters in parallel HDF5: objects must be closed before their file (the MPI-IO
// driver refuses to close a file with open objects), so declare the file handle first.
#include <hdf5.h>

#include <utility>

namespace catena::io {

template <herr_t (*CloseFunction)(hid_t)>
class Hdf5Handle {
 public:
  Hdf5Handle() = default;
  explicit Hdf5Handle(hid_t id) noexcept : id_(id) {}
  Hdf5Handle(Hdf5Handle&& other) noexcept : id_(std::exchange(other.id_, H5I_INVALID_HID)) {}
  Hdf5Handle& operator=(Hdf5Handle&& other) noexcept {
    if (this != &other) {
      close();
      id_ = std::exchange(other.id_, H5I_INVALID_HID);
    }
    return *this;
  }
  Hdf5Handle(const Hdf5Handle&) = delete;
  Hdf5Handle& operator=(const Hdf5Handle&) = delete;
  ~Hdf5Handle() { close(); }

  hid_t get() const noexcept { return id_; }

  // Closes now (idempotent); returns the HDF5 status, 0 if nothing was open.
  herr_t close() noexcept {
    if (id_ < 0) return 0;
    return CloseFunction(std::exchange(id_, H5I_INVALID_HID));
  }

  // Forgets the id without closing it: for an object of a file that can no longer be
  // written, whose close could hang or crash (ParallelHdf5File::abandon).
  hid_t release() noexcept { return std::exchange(id_, H5I_INVALID_HID); }

 private:
  hid_t id_ = H5I_INVALID_HID;
};

using FileHandle = Hdf5Handle<&H5Fclose>;
using GroupHandle = Hdf5Handle<&H5Gclose>;
using DatasetHandle = Hdf5Handle<&H5Dclose>;
using DataspaceHandle = Hdf5Handle<&H5Sclose>;
using DatatypeHandle = Hdf5Handle<&H5Tclose>;
using AttributeHandle = Hdf5Handle<&H5Aclose>;
using PropertyListHandle = Hdf5Handle<&H5Pclose>;

}  // namespace catena::io
