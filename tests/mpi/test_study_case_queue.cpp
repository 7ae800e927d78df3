// The study's groups and shared queue (src/study/case_queue.cpp) on 1, 2 and 3 ranks: every
// case number is taken exactly once, by exactly one group, and every rank of a group gets
// its group's number.
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/core/mpi_comm.hpp"
#include "catena/study/case_queue.hpp"

namespace catena::study {
namespace {

// Runs the queue until `n_cases`; returns, on world rank 0, the group that took each case
// (−1: none, −2: more than one).
std::vector<int> take_all(int ranks_per_case, int n_cases) {
  const CaseGroups groups(MPI_COMM_WORLD, ranks_per_case);
  std::vector<int> mine(static_cast<std::size_t>(n_cases), 0);
  {
    CaseQueue queue(MPI_COMM_WORLD);
    for (long k = queue.take(groups); k < n_cases; k = queue.take(groups)) {
      // Every rank of the group holds the same number.
      long lowest = k, highest = k;
      MPI_Allreduce(MPI_IN_PLACE, &lowest, 1, MPI_LONG, MPI_MIN, groups.group());
      MPI_Allreduce(MPI_IN_PLACE, &highest, 1, MPI_LONG, MPI_MAX, groups.group());
      EXPECT_EQ(lowest, highest);
      if (groups.leader()) mine[static_cast<std::size_t>(k)] = groups.index() + 1;
    }
  }
  std::vector<int> count(mine.size()), sum(mine.size());
  std::vector<int> taken(mine.size());
  for (std::size_t i = 0; i < mine.size(); ++i) taken[i] = mine[i] ? 1 : 0;
  MPI_Reduce(taken.data(), count.data(), n_cases, MPI_INT, MPI_SUM, 0, MPI_COMM_WORLD);
  MPI_Reduce(mine.data(), sum.data(), n_cases, MPI_INT, MPI_SUM, 0, MPI_COMM_WORLD);
  std::vector<int> by(mine.size());
  for (std::size_t i = 0; i < mine.size(); ++i)
    by[i] = count[i] == 0 ? -1 : count[i] > 1 ? -2 : sum[i] - 1;
  return by;
}

TEST(CaseQueue, OneRankPerCaseEveryCaseOnce) {
  const int size = mpi_size(MPI_COMM_WORLD);
  const std::vector<int> by = take_all(1, 7 * size);
  if (mpi_rank(MPI_COMM_WORLD) != 0) return;
  for (std::size_t k = 0; k < by.size(); ++k) {
    EXPECT_GE(by[k], 0) << "case " << k;
    EXPECT_LT(by[k], size) << "case " << k;
  }
}

TEST(CaseQueue, AllRanksInOneGroup) {
  const int size = mpi_size(MPI_COMM_WORLD);
  const CaseGroups groups(MPI_COMM_WORLD, size);
  EXPECT_EQ(groups.count(), 1);
  EXPECT_EQ(mpi_size(groups.group()), size);
  EXPECT_EQ(groups.leader(), mpi_rank(MPI_COMM_WORLD) == 0);
  const std::vector<int> by = take_all(size, 5);
  if (mpi_rank(MPI_COMM_WORLD) == 0) {
    for (int g : by) EXPECT_EQ(g, 0);
  }
}

TEST(CaseQueue, AfterAStopNoGroupTakesACase) {
  const CaseGroups groups(MPI_COMM_WORLD, 1);
  CaseQueue queue(MPI_COMM_WORLD);
  EXPECT_LT(queue.take(groups), CaseQueue::stopped);
  MPI_Barrier(MPI_COMM_WORLD);
  if (groups.index() == groups.count() - 1) queue.stop(groups);  // the last group stops
  MPI_Barrier(MPI_COMM_WORLD);  // (the stop is done: its epoch closed before the barrier)
  EXPECT_EQ(queue.take(groups), CaseQueue::stopped);
  EXPECT_EQ(queue.take(groups), CaseQueue::stopped);
}

TEST(CaseQueue, GroupsMustDivideTheRanks) {
  const int size = mpi_size(MPI_COMM_WORLD);
  EXPECT_THROW(CaseGroups(MPI_COMM_WORLD, 0), InputError);
  EXPECT_THROW(CaseGroups(MPI_COMM_WORLD, size + 1), InputError);
  if (size == 3) {
    EXPECT_THROW(CaseGroups(MPI_COMM_WORLD, 2), InputError);
  }
}

}  // namespace
}  // namespace catena::study
