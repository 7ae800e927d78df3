#include "catena/study/case_queue.hpp"

#include <string>

#include "catena/core/error.hpp"
#include "catena/core/mpi_comm.hpp"

namespace catena::study {

void check_ranks_per_case(MPI_Comm world, int ranks_per_case) {
  const int size = mpi_size(world);
  if (ranks_per_case < 1 || size % ranks_per_case != 0)
    throw InputError({"", 0, "--ranks-per-case"},
                     std::to_string(ranks_per_case) + " ranks per case on " + std::to_string(size) +
                         (size == 1 ? " rank" : " ranks") +
                         ": accepted: a whole number >= 1 that divides the number of "
                         "ranks (mpirun -n N)");
}

CaseGroups::CaseGroups(MPI_Comm world, int ranks_per_case) {
  check_ranks_per_case(world, ranks_per_case);
  const int size = mpi_size(world);
  const int rank = mpi_rank(world);
  index_ = rank / ranks_per_case;
  count_ = size / ranks_per_case;
  MPI_Comm_split(world, index_, rank, &group_);
  leader_ = mpi_rank(group_) == 0;
}

CaseGroups::~CaseGroups() {
  if (group_ != MPI_COMM_NULL) MPI_Comm_free(&group_);
}

// On world rank 0: [0] the next case number, [1] 1 once a group has asked every group to stop.
constexpr MPI_Aint next_slot = 0, stop_slot = 1;

CaseQueue::CaseQueue(MPI_Comm world) {
  const MPI_Aint bytes = mpi_rank(world) == 0 ? static_cast<MPI_Aint>(2 * sizeof(long)) : 0;
  MPI_Win_allocate(bytes, sizeof(long), MPI_INFO_NULL, world, &counter_, &window_);
  if (mpi_rank(world) == 0) {
    MPI_Win_lock(MPI_LOCK_EXCLUSIVE, 0, 0, window_);
    counter_[next_slot] = 0;
    counter_[stop_slot] = 0;
    MPI_Win_unlock(0, window_);
  }
  MPI_Barrier(world);  // no group takes a case before the counter is set
}

CaseQueue::~CaseQueue() {
  if (window_ != MPI_WIN_NULL) MPI_Win_free(&window_);
}

long CaseQueue::take(const CaseGroups& groups) {
  long next = 0, stop = 0;
  if (groups.leader()) {
    const long one = 1;
    MPI_Win_lock(MPI_LOCK_SHARED, 0, 0, window_);
    MPI_Fetch_and_op(&one, &next, MPI_LONG, 0, next_slot, MPI_SUM, window_);
    MPI_Fetch_and_op(nullptr, &stop, MPI_LONG, 0, stop_slot, MPI_NO_OP, window_);
    MPI_Win_unlock(0, window_);
    if (stop) next = stopped;
  }
  MPI_Bcast(&next, 1, MPI_LONG, 0, groups.group());
  return next;
}

void CaseQueue::stop(const CaseGroups& groups) {
  if (!groups.leader()) return;
  const long one = 1;
  long previous = 0;
  MPI_Win_lock(MPI_LOCK_SHARED, 0, 0, window_);
  MPI_Fetch_and_op(&one, &previous, MPI_LONG, 0, stop_slot, MPI_REPLACE, window_);
  MPI_Win_unlock(0, window_);
}

}  // namespace catena::study
