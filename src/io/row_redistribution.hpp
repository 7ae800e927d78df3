#pragma once
// From owner rows to contiguous blocks, for parallel writes of distributed arrays.
//
// A rank owns scattered rows of a global array (a partition's nodes are not a contiguous
// index range). Selecting them in the file as a union of hyperslab runs (H5S_SELECT_OR)
// costs O(n_runs²) in HDF5 1.10: 10^4 runs take 1.3 s, 10^5 runs 290 s (measured with
// 1.10.8). So the rows are first moved, with one MPI_Alltoallv, to balanced contiguous
// blocks — rank r gets rows [begin_r, begin_r + count_r) — and every rank then writes one
// contiguous hyperslab collectively. Rows stay in global (model) order, so the file does
// not depend on the number of ranks.
#include <mpi.h>

#include <cstdint>
#include <span>
#include <vector>

namespace catena::io {

// A contiguous range of global rows.
struct RowBlock {
  std::int64_t begin = 0;
  std::int64_t count = 0;
};

// Not collective. Rank `rank`'s share of n_rows rows cut into n_ranks blocks whose sizes
// differ by at most one (the first n_rows % n_ranks blocks have one row more).
RowBlock balanced_block(std::int64_t n_rows, int rank, int n_ranks);

// Not collective. The rank whose balanced block holds `row`.
int balanced_block_owner(std::int64_t row, std::int64_t n_rows, int n_ranks);

// Not collective. Throws catena::Error (naming `what`) unless `rows` is strictly ascending
// and inside [0, n_rows).
void check_rows_strictly_ascending(std::span<const int> rows, std::int64_t n_rows,
                                   const char* what);

class RowRedistribution {
 public:
  // Collective. `owned_rows`: the global rows this rank holds, strictly ascending; over
  // all ranks every row of [0, n_rows) exactly once. Throws catena::Error on every rank
  // (naming `what`, e.g. "owned_nodes") if that does not hold.
  RowRedistribution(MPI_Comm comm, std::int64_t n_rows, std::span<const int> owned_rows,
                    const char* what);

  // This rank's block: the rows it receives and writes.
  const RowBlock& block() const { return block_; }

  // Collective. `owned_values` holds n_columns values per owned row, in owned_rows order;
  // returns n_columns values per row of block(), in row order.
  std::vector<double> to_block(std::span<const double> owned_values, int n_columns) const;
  // Collective. The inverse, for reading: `block_values` holds n_columns values per row of
  // block(), in row order; returns n_columns values per owned row, in owned_rows order.
  std::vector<double> from_block(std::span<const double> block_values, int n_columns) const;

 private:
  MPI_Comm comm_;
  RowBlock block_;
  // Per peer rank, in rows: what this rank sends and receives, and where in the buffers.
  std::vector<int> send_counts_, send_offsets_, receive_counts_, receive_offsets_;
  // Received row k (peers' rows concatenated in rank order) is block row block_slot_[k].
  std::vector<std::int64_t> block_slot_;
};

}  // namespace catena::io
