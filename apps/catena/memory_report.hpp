#pragma once
// The run's peak memory per rank, printed at its end (docs/output.md, docs/performance.md).
#include "catena/core/peak_memory.hpp"

namespace catena::app {

// Rank 0 prints; the others do nothing.
void print_peak_memory(int rank, const PeakMemory& memory, int n_ranks);

}  // namespace catena::app
