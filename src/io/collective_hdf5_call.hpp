#pragma once
// Collective HDF5 calls whose outcome every rank agrees on.
//
// With the MPI-IO driver a collective call (H5Dwrite, H5Dset_extent, H5Fflush, H5Fclose,
// H5Dcreate2, ...) can fail on some ranks only: an MPI-IO aggregator finds the disk full,
// or the rank writing a piece of metadata does. A rank that threw there would skip the next
// collective call, which the others enter, and the job would hang. So right after each such
// call the ranks agree (one MPI_Allreduce) whether it failed anywhere; if so, every rank
// throws the same catena::OutputError and they all unwind through the same destructors.
//
// The message is the one of the rank that knows the cause best: a rank whose errno names
// it (the aggregator that got ENOSPC) before a rank that only saw HDF5's "file write
// failed", the lowest such rank first. If none knows it, a test write beside the file
// (space_probe.hpp) adds why that fails, if it does (a full disk, an exceeded quota).
#include <hdf5.h>
#include <mpi.h>

#include <cerrno>
#include <string_view>
#include <utility>

namespace catena::io {

// Where a call happens, for the message: "<call> failed for '<file>' at <object>: <why>".
struct Hdf5CallSite {
  std::string_view call;
  std::string_view file;
  std::string_view object = {};
};

// Collective. Agrees on the outcome of the HDF5 call at `site`, which returned `failed` on
// this rank with errno `call_errno` after it. Throws catena::OutputError on every rank if
// it failed on any — or if the write-fault testing hook injects a failure here
// (catena/io/write_fault_injection.hpp).
void agree_on_hdf5_call(MPI_Comm comm, const Hdf5CallSite& site, bool failed, int call_errno);

// Collective. Runs `call` (a collective HDF5 call returning herr_t or hid_t, negative on
// failure) on every rank and agrees on its outcome (above); returns what it returned.
template <class Call>
auto agreed_hdf5_call(MPI_Comm comm, const Hdf5CallSite& site, Call&& call) {
  errno = 0;
  const auto result = std::forward<Call>(call)();
  const int call_errno = errno;
  agree_on_hdf5_call(comm, site, result < 0, call_errno);
  return result;
}

// Collective. Runs `create` (a collective HDF5 call returning a new id) and takes the id
// into a Handle before agreeing, so that a rank where it succeeded closes it when another
// rank's failure makes every rank throw.
template <class Handle, class Create>
Handle agreed_hdf5_create(MPI_Comm comm, const Hdf5CallSite& site, Create&& create) {
  errno = 0;
  Handle handle(std::forward<Create>(create)());
  const int call_errno = errno;
  agree_on_hdf5_call(comm, site, handle.get() < 0, call_errno);
  return handle;
}

}  // namespace catena::io
