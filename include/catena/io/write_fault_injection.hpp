#pragma once
// A testing hook: make one HDF5 write call on one rank report failure, as if the disk had
// filled up there, to test that a write error on one rank becomes the same clean error on
// every rank (docs/output.md, "When the output cannot be written").
//
//   CATENA_FAULT_INJECT_WRITE="rank=R,call=N[,at=TEXT]"
//
// On MPI_COMM_WORLD rank R, the N-th (1-based) write call — H5Dwrite, H5Fflush or H5Fclose
// through the io layer — whose file path or object name contains TEXT (any, if not given)
// runs as usual on every rank and then reports "No space left on device" on rank R. The
// variable is read once, at the first write call; unset, the hook costs one test of a
// flag per write call.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace catena::io {

struct WriteFault {
  int rank = 0;           // of MPI_COMM_WORLD
  std::int64_t call = 1;  // 1-based, counting matching write calls on that rank
  std::string at;         // substring of the file path or object name; empty: any
};

// Not collective. Parses the value of CATENA_FAULT_INJECT_WRITE; throws catena::Error
// saying what is accepted.
WriteFault parse_write_fault(std::string_view text);

// Not collective. Replaces the fault to inject (std::nullopt: none) and restarts the count,
// for tests that inject several faults in one process. Overrides the environment.
void set_write_fault(std::optional<WriteFault> fault);

}  // namespace catena::io
