#pragma once
// When a dynamic run flushes its output and writes a checkpoint: on the wall clock, and the
// same decision on every rank.
//
// Flushes and checkpoints are collective (parallel HDF5), so a rank that flushes while
// another goes on stepping deadlocks the job. MPI_Wtime has a per-process origin in Open
// MPI (MPI_WTIME_IS_GLOBAL is false), so ranks cannot compare each other's clock readings:
// only rank 0 reads the clock and keeps the times of the last flush and checkpoint, and its
// decision is broadcast. Nothing clock-dependent is kept on the other ranks.
#include <mpi.h>

#include <functional>

namespace catena::app {

class WallClockSchedule {
 public:
  enum class Action { none, flush, checkpoint };  // a checkpoint flushes too
  struct Periods {
    double flush_seconds = 10.0;
    double checkpoint_seconds = 0.0;  // <= 0: no checkpoints on the clock
  };
  // Seconds from an arbitrary origin; read on rank 0 only. Tests substitute their own.
  using Clock = std::function<double()>;

  // Collective. The periods start now (rank 0's clock).
  WallClockSchedule(MPI_Comm comm, const Periods& periods, Clock clock = MPI_Wtime);

  // Collective. What is due now; the same on every rank. The period of what is returned
  // restarts (a checkpoint restarts the flush period too).
  Action due();

 private:
  MPI_Comm comm_;
  Periods periods_;
  Clock clock_;
  bool is_root_ = false;
  double last_flush_ = 0.0, last_checkpoint_ = 0.0;  // rank 0's clock; unused elsewhere
};

}  // namespace catena::app
