#include "row_redistribution.hpp"

#include <algorithm>
#include <string>

#include "catena/core/error.hpp"
#include "catena/core/mpi_comm.hpp"
#include "collective_phase.hpp"

namespace catena::io {
namespace {

std::vector<int> exclusive_prefix_sum(const std::vector<int>& counts) {
  std::vector<int> offsets(counts.size(), 0);
  for (std::size_t i = 1; i < counts.size(); ++i) offsets[i] = offsets[i - 1] + counts[i - 1];
  return offsets;
}

// Where each received row goes in the block; checks that the peers together delivered
// every row of the block exactly once (i.e. ownership is disjoint and complete).
std::vector<std::int64_t> block_slots_covering_once(const std::vector<int>& received_rows,
                                                    const RowBlock& block, const char* what) {
  std::vector<std::int64_t> slots(received_rows.size());
  std::vector<char> delivered(static_cast<std::size_t>(block.count), 0);
  for (std::size_t k = 0; k < received_rows.size(); ++k) {
    const std::int64_t slot = received_rows[k] - block.begin;
    CATENA_ASSERT(slot >= 0 && slot < block.count, "row sent to the wrong block");
    if (delivered[static_cast<std::size_t>(slot)])
      throw Error("row " + std::to_string(received_rows[k]) + " of " + what +
                  " is owned by more than one rank");
    delivered[static_cast<std::size_t>(slot)] = 1;
    slots[k] = slot;
  }
  const auto missing = std::find(delivered.begin(), delivered.end(), 0);
  if (missing != delivered.end())
    throw Error("row " + std::to_string(block.begin + (missing - delivered.begin())) + " of " +
                what + " is owned by no rank");
  return slots;
}

// A committed MPI datatype, freed on scope exit.
class CommittedDatatype {
 public:
  CommittedDatatype(int n_values, MPI_Datatype value_type) {
    MPI_Type_contiguous(n_values, value_type, &type_);
    MPI_Type_commit(&type_);
  }
  ~CommittedDatatype() { MPI_Type_free(&type_); }
  CommittedDatatype(const CommittedDatatype&) = delete;
  CommittedDatatype& operator=(const CommittedDatatype&) = delete;
  MPI_Datatype get() const { return type_; }

 private:
  MPI_Datatype type_ = MPI_DATATYPE_NULL;
};

}  // namespace

void check_rows_strictly_ascending(std::span<const int> rows, std::int64_t n_rows,
                                   const char* what) {
  for (std::size_t k = 0; k < rows.size(); ++k) {
    if (rows[k] < 0 || rows[k] >= n_rows)
      throw Error(std::string(what) + "[" + std::to_string(k) + "] = " + std::to_string(rows[k]) +
                  " is outside [0, " + std::to_string(n_rows) + ")");
    if (k > 0 && rows[k] <= rows[k - 1])
      throw Error(std::string(what) + " must be strictly ascending, but entry " +
                  std::to_string(k) + " is " + std::to_string(rows[k]) + " after " +
                  std::to_string(rows[k - 1]));
  }
}

RowBlock balanced_block(std::int64_t n_rows, int rank, int n_ranks) {
  const std::int64_t base = n_rows / n_ranks;
  const std::int64_t n_larger = n_rows % n_ranks;  // blocks with base + 1 rows come first
  return {rank * base + std::min<std::int64_t>(rank, n_larger), base + (rank < n_larger ? 1 : 0)};
}

int balanced_block_owner(std::int64_t row, std::int64_t n_rows, int n_ranks) {
  const std::int64_t base = n_rows / n_ranks;
  const std::int64_t n_larger = n_rows % n_ranks;
  const std::int64_t end_of_larger = n_larger * (base + 1);
  if (row < end_of_larger) return static_cast<int>(row / (base + 1));
  return static_cast<int>(n_larger + (row - end_of_larger) / base);
}

RowRedistribution::RowRedistribution(MPI_Comm comm, std::int64_t n_rows,
                                     std::span<const int> owned_rows, const char* what)
    : comm_(comm), block_(balanced_block(n_rows, mpi_rank(comm), mpi_size(comm))) {
  // Local check first, in its own phase, so that no rank enters the exchange alone.
  run_collective_phase(comm, [&] { check_rows_strictly_ascending(owned_rows, n_rows, what); });

  const int n_ranks = mpi_size(comm);
  send_counts_.assign(static_cast<std::size_t>(n_ranks), 0);
  // Ascending rows go to non-decreasing destinations, so the owned arrays are already laid
  // out peer by peer: they are the send buffers, no packing needed.
  for (const int row : owned_rows) ++send_counts_[balanced_block_owner(row, n_rows, n_ranks)];
  receive_counts_.assign(static_cast<std::size_t>(n_ranks), 0);
  MPI_Alltoall(send_counts_.data(), 1, MPI_INT, receive_counts_.data(), 1, MPI_INT, comm);
  send_offsets_ = exclusive_prefix_sum(send_counts_);
  receive_offsets_ = exclusive_prefix_sum(receive_counts_);

  std::vector<int> received_rows(
      static_cast<std::size_t>(receive_offsets_.back() + receive_counts_.back()));
  MPI_Alltoallv(owned_rows.data(), send_counts_.data(), send_offsets_.data(), MPI_INT,
                received_rows.data(), receive_counts_.data(), receive_offsets_.data(), MPI_INT,
                comm);
  block_slot_ = run_collective_phase(
      comm, [&] { return block_slots_covering_once(received_rows, block_, what); });
}

std::vector<double> RowRedistribution::to_block(std::span<const double> owned_values,
                                                int n_columns) const {
  CATENA_ASSERT(n_columns >= 1, "a row has at least one value");
  CATENA_ASSERT(
      owned_values.size() == static_cast<std::size_t>(send_offsets_.back() + send_counts_.back()) *
                                 static_cast<std::size_t>(n_columns),
      "one row of values per owned row");
  const CommittedDatatype row_type(n_columns, MPI_DOUBLE);
  const auto columns = static_cast<std::size_t>(n_columns);
  std::vector<double> received(block_slot_.size() * columns);
  MPI_Alltoallv(owned_values.data(), send_counts_.data(), send_offsets_.data(), row_type.get(),
                received.data(), receive_counts_.data(), receive_offsets_.data(), row_type.get(),
                comm_);

  std::vector<double> block_values(static_cast<std::size_t>(block_.count) * columns);
  for (std::size_t k = 0; k < block_slot_.size(); ++k)
    std::copy_n(received.begin() + static_cast<std::ptrdiff_t>(k * columns), columns,
                block_values.begin() + static_cast<std::ptrdiff_t>(
                                           static_cast<std::size_t>(block_slot_[k]) * columns));
  return block_values;
}

std::vector<double> RowRedistribution::from_block(std::span<const double> block_values,
                                                  int n_columns) const {
  CATENA_ASSERT(n_columns >= 1, "a row has at least one value");
  CATENA_ASSERT(block_values.size() ==
                    static_cast<std::size_t>(block_.count) * static_cast<std::size_t>(n_columns),
                "one row of values per block row");
  const CommittedDatatype row_type(n_columns, MPI_DOUBLE);
  const auto columns = static_cast<std::size_t>(n_columns);
  // The rows each peer sent to_block, in the order it sent them, go back to it.
  std::vector<double> sent(block_slot_.size() * columns);
  for (std::size_t k = 0; k < block_slot_.size(); ++k)
    std::copy_n(block_values.begin() +
                    static_cast<std::ptrdiff_t>(static_cast<std::size_t>(block_slot_[k]) * columns),
                columns, sent.begin() + static_cast<std::ptrdiff_t>(k * columns));
  std::vector<double> owned(static_cast<std::size_t>(send_offsets_.back() + send_counts_.back()) *
                            columns);
  MPI_Alltoallv(sent.data(), receive_counts_.data(), receive_offsets_.data(), row_type.get(),
                owned.data(), send_counts_.data(), send_offsets_.data(), row_type.get(), comm_);
  return owned;
}

}  // namespace catena::io
