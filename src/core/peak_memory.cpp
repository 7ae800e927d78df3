#include "catena/core/peak_memory.hpp"

#include <sys/resource.h>

namespace catena {

double process_peak_memory_bytes() {
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0) return 0.0;
  // Linux reports ru_maxrss in kibibytes.
  return static_cast<double>(usage.ru_maxrss) * 1024.0;
}

PeakMemory peak_memory(MPI_Comm comm) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  const double mine = process_peak_memory_bytes();
  struct {
    double value;
    int rank;
  } local{mine, rank}, largest{0.0, 0};
  MPI_Allreduce(&local, &largest, 1, MPI_DOUBLE_INT, MPI_MAXLOC, comm);
  PeakMemory p;
  p.largest_bytes = largest.value;
  p.largest_rank = largest.rank;
  MPI_Allreduce(&mine, &p.smallest_bytes, 1, MPI_DOUBLE, MPI_MIN, comm);
  MPI_Allreduce(&mine, &p.total_bytes, 1, MPI_DOUBLE, MPI_SUM, comm);
  return p;
}

}  // namespace catena
