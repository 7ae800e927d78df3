#pragma once
// HDF5 status codes → catena::Error. Every HDF5 call in the io layer goes through one of
// these checks, so a failure names the call, the file and the object, plus the most
// specific message from HDF5's error stack (e.g. MPI_File_open's "no such file").
#include <hdf5.h>

#include <string>
#include <string_view>

#include "catena/core/error.hpp"
#include "catena/io/output_error.hpp"

namespace catena::io {

// Not collective. Whether errno `error_number` says why data could not be written to an
// open file (no space left, quota exceeded, I/O error, read-only file system, ...). Other
// values are no evidence: EAGAIN or EINTR may be left behind by MPI's progress engine,
// ENOENT by HDF5 probing for a file.
bool names_a_write_cause(int error_number);

// Not collective. "<call> failed for '<file>' [at <object>]: <why>", with <why> taken from
// the innermost entry of HDF5's default error stack, which it clears. `call_errno`: errno
// right after the call (0: not known); if names_a_write_cause(call_errno), its text leads
// <why>: HDF5's MPI-IO driver reports a short write only as "file write failed".
std::string hdf5_failure_message(std::string_view call, std::string_view file,
                                 std::string_view object = {}, int call_errno = 0);

// Not collective. Throws catena::Error with hdf5_failure_message(call, file, object).
[[noreturn]] void throw_hdf5_error(std::string_view call, std::string_view file,
                                   std::string_view object = {});

// Not collective. Returns `id` if valid, else throws as above.
hid_t checked_hdf5_id(hid_t id, std::string_view call, std::string_view file,
                      std::string_view object = {});

// Not collective. Throws as above if `status` is negative.
void check_hdf5_status(herr_t status, std::string_view call, std::string_view file,
                       std::string_view object = {});

// While alive, HDF5 does not print its error stack to stderr: failures are reported once,
// as exceptions, instead of as a screenful per rank. Restores the previous handler.
class Hdf5ErrorPrintingSuppressed {
 public:
  Hdf5ErrorPrintingSuppressed();
  ~Hdf5ErrorPrintingSuppressed();
  Hdf5ErrorPrintingSuppressed(const Hdf5ErrorPrintingSuppressed&) = delete;
  Hdf5ErrorPrintingSuppressed& operator=(const Hdf5ErrorPrintingSuppressed&) = delete;

 private:
  H5E_auto2_t previous_handler_ = nullptr;
  void* previous_data_ = nullptr;
};

// Collective as `write` is. Writes a result file: runs `write` with HDF5's error printing
// off; a failure (agreed between the ranks by `write`'s phases and agreed HDF5 calls)
// becomes an OutputError naming `path`.
template <class Write>
void write_result_file(const std::string& path, Write&& write) {
  const Hdf5ErrorPrintingSuppressed quiet_hdf5;
  try {
    write();
  } catch (const Error& agreed) {
    throw OutputError("cannot write '" + path + "': " + agreed.what());
  }
}

}  // namespace catena::io
