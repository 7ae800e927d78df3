#include "wall_clock_schedule.hpp"

#include <utility>

namespace catena::app {

WallClockSchedule::WallClockSchedule(MPI_Comm comm, const Periods& periods, Clock clock)
    : comm_(comm), periods_(periods), clock_(std::move(clock)) {
  int rank = 0;
  MPI_Comm_rank(comm_, &rank);
  is_root_ = rank == 0;
  if (is_root_) last_flush_ = last_checkpoint_ = clock_();
}

WallClockSchedule::Action WallClockSchedule::due() {
  int action = static_cast<int>(Action::none);
  if (is_root_) {
    const double now = clock_();
    if (periods_.checkpoint_seconds > 0.0 &&
        now - last_checkpoint_ >= periods_.checkpoint_seconds) {
      action = static_cast<int>(Action::checkpoint);
      last_checkpoint_ = last_flush_ = now;
    } else if (now - last_flush_ >= periods_.flush_seconds) {
      action = static_cast<int>(Action::flush);
      last_flush_ = now;
    }
  }
  MPI_Bcast(&action, 1, MPI_INT, 0, comm_);
  return static_cast<Action>(action);
}

}  // namespace catena::app
