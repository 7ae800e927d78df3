#pragma once
// Peak resident memory of the ranks of a run (the operating system's high-water mark of
// each process, getrusage's ru_maxrss): what a user sizes a cluster job's memory request
// by, and how a run shows that adding ranks spreads its model (docs/performance.md).
#include <mpi.h>

namespace catena {

struct PeakMemory {
  double largest_bytes = 0.0;  // the rank with the most
  int largest_rank = 0;
  double smallest_bytes = 0.0;  // the rank with the least
  double total_bytes = 0.0;     // summed over the ranks
};

// This process's peak resident memory so far, bytes (0 where the system does not say).
double process_peak_memory_bytes();

// Collective over `comm`.
PeakMemory peak_memory(MPI_Comm comm);

}  // namespace catena
