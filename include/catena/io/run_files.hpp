#pragma once
// The files of one dynamic run with output name OUT.h5, and how they change hands:
//   OUT.part.h5   the time series while the run is going, or after it was interrupted or
//                 failed (status "running", "interrupted" or "failed: ..."); a restart
//                 continues it;
//   OUT.h5        the time series of a run that completed: renamed from OUT.part.h5 at
//                 the end, atomically, so an earlier complete result is replaced only by
//                 a complete one;
//   OUT.h5.chk    the latest checkpoint (checkpoint.hpp), with the run's id;
//   OUT.h5.lock   held while a run uses these names (output_lock.hpp).
// The run id (random, made at the run's start) is stored in the checkpoint and in the
// time series, so a restart continues only the file that belongs to its checkpoint.
#include <mpi.h>

#include <string>

namespace catena::io {

// "dir/OUT.part.h5" for "dir/OUT.h5" (the extension kept, so tools still see HDF5).
std::string partial_output_path(const std::string& output_path);
inline std::string checkpoint_path(const std::string& output_path) { return output_path + ".chk"; }

// Collective. A new run id (made on rank 0, broadcast): 32 hex digits.
std::string new_run_id(MPI_Comm comm);

// Not collective. The `run_id` attribute of the time-series file `path`; "" if the file is
// missing, unreadable or has none.
std::string read_run_id(const std::string& path);

// Not collective. Removes temporary checkpoint files ("OUT.h5.chk.tmp-PID") that a run
// killed while writing a checkpoint left behind. Call only while holding the output lock
// (then no other run is writing them). Returns how many were removed.
int remove_abandoned_checkpoint_temporaries(const std::string& output_path);

}  // namespace catena::io
