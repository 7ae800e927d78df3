#pragma once
// For tests that read HDF5 files themselves (serial HDF5, independently of the io layer).
#include <hdf5.h>

namespace catena::test {

// Any HDF5 identifier, released on scope exit (H5Idec_ref closes whatever kind it is).
class OpenId {
 public:
  explicit OpenId(hid_t id) : id_(id) {}
  ~OpenId() {
    if (id_ >= 0) H5Idec_ref(id_);
  }
  OpenId(const OpenId&) = delete;
  OpenId& operator=(const OpenId&) = delete;
  hid_t get() const { return id_; }

 private:
  hid_t id_;
};

}  // namespace catena::test
