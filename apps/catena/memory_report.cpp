#include "memory_report.hpp"

#include <cstdio>

namespace catena::app {

void print_peak_memory(int rank, const PeakMemory& memory, int n_ranks) {
  if (rank != 0 || memory.largest_bytes <= 0.0) return;
  constexpr double mib = 1024.0 * 1024.0;
  if (n_ranks == 1) {
    std::printf("peak memory %.0f MiB\n", memory.largest_bytes / mib);
    return;
  }
  std::printf("peak memory per rank %.0f MiB (rank %d) to %.0f MiB, %.0f MiB over %d ranks\n",
              memory.largest_bytes / mib, memory.largest_rank, memory.smallest_bytes / mib,
              memory.total_bytes / mib, n_ranks);
}

}  // namespace catena::app
