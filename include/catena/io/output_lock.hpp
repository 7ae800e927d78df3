#pragma once
// One run at a time per output name. A run holds an exclusive lock on "<output>.lock" for
// its lifetime, so a second run given the same output name (and so the same checkpoint and
// partial-output names) is refused at once instead of interleaving rows with the first.
//
// flock(2) on the lock file, taken by rank 0 only (the other ranks learn the outcome): the
// kernel drops the lock when the process dies, however it dies, so a crashed run never
// leaves a stale lock. The file holds the owner's pid and host for the refusal message and
// is removed when the lock is released. flock works across NFS clients on Linux (emulated
// with byte-range locks); on Lustre it needs the `flock` mount option.
#include <mpi.h>

#include <string>

namespace catena::io {

class OutputLock {
 public:
  // Collective. Locks `output_path` + ".lock". Throws catena::InputError (on every rank)
  // naming the output, the holder's pid and host, if another process holds it, and
  // catena::Error if the lock file cannot be created (the directory's problem, named).
  OutputLock(MPI_Comm comm, const std::string& output_path);
  // Not collective. Removes the lock file and releases the lock (rank 0).
  ~OutputLock();
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

  static std::string lock_path(const std::string& output_path) { return output_path + ".lock"; }

 private:
  std::string path_;
  int fd_ = -1;  // rank 0's descriptor holding the lock; -1 elsewhere
};

}  // namespace catena::io
