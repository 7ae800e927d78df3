#pragma once
// After a write failed: can anything still be written where the file is?
#include <mpi.h>

#include <filesystem>
#include <string>

namespace catena::io {

// Collective. Rank 0 writes, fsyncs and removes "<path>.probe.tmp-<pid>", 1 MiB; returns
// why that failed ("" if it did not), the same on every rank. It tells a full disk, an
// exceeded quota or a failing file system — where writing a file's last metadata would
// fail again, and HDF5 1.10 may hang when that fails on some ranks only — from a failure
// that is not met again.
std::string failed_test_write_beside(MPI_Comm comm, const std::filesystem::path& path);

}  // namespace catena::io
