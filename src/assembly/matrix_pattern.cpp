// SecondOrderSystem::create_matrix: a matrix holding the union of the couplings' patterns
// over this rank's rows (part of the class: include/catena/assembly/second_order_system.hpp).
//
// Each row of the ghosted local form visits the couplings of this rank that touch it and
// marks the columns it has seen (one integer per local column). A coupling on this rank
// also writes into rows another rank owns (a node on the partition boundary): those rows'
// columns are sent to their owner, which merges them into its own. The owned rows are
// visited twice, once to count each row's entries for the preallocation and once to insert
// them as zeros. Why not PETSc's MATPREALLOCATOR: a dense coupling of n DOFs names n²
// pairs, most shared with its neighbours, and the preallocator hashes every one (about 6 %
// of the moving-load benchmark's process); why not compressed rows handed to PETSc whole:
// they hold a second copy of the pattern while the matrix is allocated. Here the extra
// memory is one row, the row → coupling incidence and the boundary rows received from
// other ranks.
#include <algorithm>
#include <cstdint>

#include "catena/assembly/petsc_call.hpp"
#include "catena/assembly/second_order_system.hpp"
#include "catena/core/mpi_comm.hpp"

namespace catena::assembly {
namespace {

// The couplings at each row of the ghosted local form, and the union of their patterns
// per row on request.
class RowCouplings {
 public:
  // offset: per coupling, its first entry in local_index/global_index (and one past the
  // last coupling's); local_index: ghosted local index or −1; global_index likewise.
  RowCouplings(const couplings::CouplingList& list, const std::vector<size_t>& offset,
               const std::vector<PetscInt>& local_index, const std::vector<PetscInt>& global_index,
               size_t n_local)
      : list_(list), offset_(offset), local_(local_index), global_(global_index) {
    // Sparse couplings: per position, the positions its row may couple (from pattern()).
    sparse_columns_.resize(list.size());
    std::vector<std::pair<int, int>> entries;
    for (size_t i = 0; i < list.size(); ++i) {
      if (list[i]->dense()) continue;
      list[i]->pattern(entries);
      auto& columns = sparse_columns_[i];
      columns.assign(offset[i + 1] - offset[i], {});
      for (auto [r, c] : entries) columns[static_cast<size_t>(r)].push_back(c);
    }
    // The (coupling, position) pairs at each local row, compressed by row.
    start_.assign(n_local + 1, 0);
    for (const PetscInt row : local_index)
      if (row >= 0) ++start_[static_cast<size_t>(row) + 1];
    for (size_t r = 0; r < n_local; ++r) start_[r + 1] += start_[r];
    at_.resize(start_.back());
    std::vector<size_t> next(start_.begin(), start_.end() - 1);
    for (size_t i = 0; i < list.size(); ++i)
      for (size_t k = offset[i]; k < offset[i + 1]; ++k)
        if (const PetscInt row = local_index[k]; row >= 0)
          at_[next[static_cast<size_t>(row)]++] = {static_cast<std::uint32_t>(i),
                                                   static_cast<std::uint32_t>(k - offset[i])};
    seen_in_row_.resize(n_local);
  }

  // Calls fn(local row, columns) for the local rows [begin, end): the global columns of
  // the couplings' patterns there, unsorted, each once (fn may change them).
  template <class Fn>
  void visit(size_t begin, size_t end, Fn&& fn) {
    // A visit marks columns with its rows' indices, so an earlier visit's marks must go.
    std::fill(seen_in_row_.begin(), seen_in_row_.end(), kNoRow);
    for (size_t row = begin; row < end; ++row) {
      columns_.clear();
      const auto add = [&](size_t k) {
        const PetscInt local = local_[k];
        if (local < 0 || seen_in_row_[static_cast<size_t>(local)] == row) return;
        seen_in_row_[static_cast<size_t>(local)] = row;
        columns_.push_back(global_[k]);
      };
      for (size_t j = start_[row]; j < start_[row + 1]; ++j) {
        const size_t i = at_[j].coupling, first = offset_[i];
        if (list_[i]->dense()) {
          for (size_t k = first; k < offset_[i + 1]; ++k) add(k);
        } else {
          for (int c : sparse_columns_[i][at_[j].position]) add(first + static_cast<size_t>(c));
        }
      }
      fn(row, columns_);
    }
  }

 private:
  struct Incidence {
    std::uint32_t coupling, position;
  };
  static constexpr size_t kNoRow = static_cast<size_t>(-1);
  const couplings::CouplingList& list_;
  const std::vector<size_t>& offset_;
  const std::vector<PetscInt>& local_;
  const std::vector<PetscInt>& global_;
  std::vector<std::vector<std::vector<int>>> sparse_columns_;
  std::vector<size_t> start_;  // per local row, into at_
  std::vector<Incidence> at_;
  std::vector<size_t> seen_in_row_;  // per local column: the last row that listed it
  std::vector<PetscInt> columns_;
};

// Sends each ghost row's columns to the rank owning the row; returns, per owned row, the
// columns other ranks' couplings put there (global indices, in no order, maybe repeated).
std::vector<std::vector<PetscInt>> exchange_boundary_rows(MPI_Comm comm, const DofMap& dofs,
                                                          RowCouplings& rows) {
  const int size = mpi_size(comm);
  std::vector<PetscInt> owned_counts(static_cast<size_t>(size));
  const PetscInt n_owned = dofs.n_owned();
  MPI_Allgather(&n_owned, 1, MPIU_INT, owned_counts.data(), 1, MPIU_INT, comm);
  std::vector<PetscInt> range_start(static_cast<size_t>(size) + 1, 0);
  for (int r = 0; r < size; ++r) range_start[r + 1] = range_start[r] + owned_counts[r];

  // Per destination: [global row, count, columns...] for each of its rows.
  std::vector<std::vector<PetscInt>> out(static_cast<size_t>(size));
  const auto owned = static_cast<size_t>(n_owned);
  rows.visit(owned, owned + dofs.ghosts().size(), [&](size_t local_row, auto& columns) {
    if (columns.empty()) return;
    const PetscInt row = dofs.ghosts()[local_row - owned];
    const auto owner = static_cast<size_t>(
        std::upper_bound(range_start.begin(), range_start.end(), row) - range_start.begin() - 1);
    out[owner].push_back(row);
    out[owner].push_back(static_cast<PetscInt>(columns.size()));
    out[owner].insert(out[owner].end(), columns.begin(), columns.end());
  });
  std::vector<int> send_counts(static_cast<size_t>(size)), recv_counts(static_cast<size_t>(size));
  for (int r = 0; r < size; ++r) send_counts[r] = static_cast<int>(out[r].size());
  MPI_Alltoall(send_counts.data(), 1, MPI_INT, recv_counts.data(), 1, MPI_INT, comm);
  std::vector<int> send_offsets(static_cast<size_t>(size) + 1, 0),
      recv_offsets(static_cast<size_t>(size) + 1, 0);
  for (int r = 0; r < size; ++r) {
    send_offsets[r + 1] = send_offsets[r] + send_counts[r];
    recv_offsets[r + 1] = recv_offsets[r] + recv_counts[r];
  }
  std::vector<PetscInt> sent, received(static_cast<size_t>(recv_offsets.back()));
  for (const auto& block : out) sent.insert(sent.end(), block.begin(), block.end());
  MPI_Alltoallv(sent.data(), send_counts.data(), send_offsets.data(), MPIU_INT, received.data(),
                recv_counts.data(), recv_offsets.data(), MPIU_INT, comm);

  std::vector<std::vector<PetscInt>> remote(owned);
  const PetscInt first = dofs.first_owned();
  for (size_t at = 0; at < received.size();) {
    const PetscInt row = received[at], count = received[at + 1];
    auto& columns = remote[static_cast<size_t>(row - first)];
    columns.insert(columns.end(), received.begin() + static_cast<std::ptrdiff_t>(at) + 2,
                   received.begin() + static_cast<std::ptrdiff_t>(at) + 2 + count);
    at += 2 + static_cast<size_t>(count);
  }
  return remote;
}

}  // namespace

MatHandle SecondOrderSystem::create_matrix() const {
  const PetscInt n = dofs_.n_owned(), N = dofs_.n_global(), first = dofs_.first_owned();
  RowCouplings rows(couplings_, offset_, local_index_, global_index_,
                    static_cast<size_t>(n) + dofs_.ghosts().size());
  std::vector<std::vector<PetscInt>> remote;
  if (mpi_size(comm_) > 1) remote = exchange_boundary_rows(comm_, dofs_, rows);
  // Each owned row's columns: this rank's, merged with other ranks' where there are any,
  // and the diagonal, which a multiplier's row lacks (its constraint does not involve it)
  // and PETSc's LU needs in the pattern (constraints_last_ordering.hpp).
  const auto visit_owned = [&](auto&& fn) {
    rows.visit(0, static_cast<size_t>(n), [&](size_t row, std::vector<PetscInt>& columns) {
      if (!remote.empty() && !remote[row].empty()) {
        columns.insert(columns.end(), remote[row].begin(), remote[row].end());
        std::sort(columns.begin(), columns.end());
        columns.erase(std::unique(columns.begin(), columns.end()), columns.end());
      }
      const PetscInt global_row = first + static_cast<PetscInt>(row);
      if (std::find(columns.begin(), columns.end(), global_row) == columns.end())
        columns.push_back(global_row);
      fn(global_row, columns);
    });
  };

  std::vector<PetscInt> diagonal(static_cast<size_t>(n), 0),
      off_diagonal(static_cast<size_t>(n), 0);
  size_t longest = 0;
  visit_owned([&](PetscInt row, const std::vector<PetscInt>& columns) {
    for (PetscInt c : columns)
      ++(c >= first && c < first + n ? diagonal : off_diagonal)[static_cast<size_t>(row - first)];
    longest = std::max(longest, columns.size());
  });
  MatHandle J;
  CATENA_PETSC(MatCreate(comm_, J.out()));
  CATENA_PETSC(MatSetSizes(J.get(), n, n, N, N));
  CATENA_PETSC(MatSetType(J.get(), MATAIJ));
  CATENA_PETSC(MatSeqAIJSetPreallocation(J.get(), 0, diagonal.data()));
  CATENA_PETSC(MatMPIAIJSetPreallocation(J.get(), 0, diagonal.data(), 0, off_diagonal.data()));
  CATENA_PETSC(MatSetOption(J.get(), MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
  CATENA_PETSC(MatSetOption(J.get(), MAT_IGNORE_ZERO_ENTRIES, PETSC_FALSE));
  const std::vector<double> zeros(longest, 0.0);
  visit_owned([&](PetscInt row, std::vector<PetscInt>& columns) {
    std::sort(columns.begin(), columns.end());
    CATENA_PETSC(MatSetValues(J.get(), 1, &row, static_cast<PetscInt>(columns.size()),
                              columns.data(), zeros.data(), INSERT_VALUES));
  });
  CATENA_PETSC(MatAssemblyBegin(J.get(), MAT_FINAL_ASSEMBLY));
  CATENA_PETSC(MatAssemblyEnd(J.get(), MAT_FINAL_ASSEMBLY));
  return J;
}

}  // namespace catena::assembly
