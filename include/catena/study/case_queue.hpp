#pragma once
// Cases of a study run concurrently (`mpirun -n N catena study ... --ranks-per-case k`):
// the ranks split into N/k groups of k consecutive ranks, each a communicator of its own
// that runs one case at a time, and the groups take cases from one shared queue — a
// counter on rank 0 of the whole run, read and incremented atomically (MPI one-sided
// fetch-and-op), so a group that finishes early takes the next case instead of waiting
// for a fixed share. docs/study.md, "Cases in parallel".
#include <mpi.h>

namespace catena::study {

// Not collective. Throws catena::InputError (key "--ranks-per-case") unless
// 1 <= ranks_per_case and it divides the number of ranks of `world`.
void check_ranks_per_case(MPI_Comm world, int ranks_per_case);

class CaseGroups {
 public:
  // Collective over `world`. Throws as check_ranks_per_case.
  CaseGroups(MPI_Comm world, int ranks_per_case);
  ~CaseGroups();
  CaseGroups(const CaseGroups&) = delete;
  CaseGroups& operator=(const CaseGroups&) = delete;

  MPI_Comm group() const { return group_; }  // this rank's group
  int index() const { return index_; }       // 0 .. count() − 1
  int count() const { return count_; }
  bool leader() const { return leader_; }  // rank 0 of its group

 private:
  MPI_Comm group_ = MPI_COMM_NULL;
  int index_ = 0;
  int count_ = 1;
  bool leader_ = false;
};

// The shared queue: case numbers 0, 1, 2, ... handed out once each across all groups.
class CaseQueue {
 public:
  // Collective over `world` (the communicator the groups were split from).
  explicit CaseQueue(MPI_Comm world);
  // Collective over `world`: every rank must have stopped taking cases.
  ~CaseQueue();
  CaseQueue(const CaseQueue&) = delete;
  CaseQueue& operator=(const CaseQueue&) = delete;

  // Collective over groups.group(): the group's next case number (the leader takes it from
  // the queue; every rank of the group gets the same). Numbers grow without bound: the
  // caller stops at its number of cases. After stop(), `stopped` for every group.
  long take(const CaseGroups& groups);
  static constexpr long stopped = 0x7fffffffL;

  // Not collective (the group's leader acts): no group takes another case (a case was
  // interrupted: the study stops as a run does after SIGTERM).
  void stop(const CaseGroups& groups);

 private:
  MPI_Win window_ = MPI_WIN_NULL;
  long* counter_ = nullptr;  // on world rank 0: the next case number, the stop flag
};

}  // namespace catena::study
