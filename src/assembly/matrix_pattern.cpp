// SecondOrderSystem::create_matrix: a matrix holding the union of the couplings' patterns
// over this rank's rows (part of the class: include/catena/assembly/second_order_system.hpp).
//
// Each row of the ghosted local form visits the couplings of this rank that touch it and
// marks the columns it has seen (one integer per local column). A coupling on this rank
// also writes into rows another rank owns (a node on the partition boundary): those rows'
// columns are sent to their owner, which merges them into its own. The owned rows are
// visited twice, once to count each row's entries for the preallocation and once to insert
// them as zeros. Why not PETSc's MATPREALLOCATOR: a dense coupling of n DOFs names n²
// pairs, most shared with its neighbours, and the preallocator hashes every one (about 7 %
// of the moving-load benchmark's process); why not compressed rows handed to PETSc whole:
// they held a second copy of the pattern while the matrix was allocated, which raised the
// run's peak memory (docs/performance.md). Here the extra memory is one row, the row →
// coupling incidence and the boundary rows received from other ranks.
#include <algorithm>
#include <cstdint>
#include <functional>

#include "catena/assembly/petsc_call.hpp"
#include "catena/assembly/second_order_system.hpp"
#include "catena/core/mpi_comm.hpp"

namespace catena::assembly {

template <class Fn>
void SecondOrderSystem::visit_pattern_rows(Fn&& fn) const {
  const size_t n_local = static_cast<size_t>(dofs_.n_owned()) + dofs_.ghosts().size();

  // Sparse couplings: per position, the positions its row may couple (from pattern()).
  std::vector<std::vector<std::vector<int>>> sparse_columns(couplings_.size());
  std::vector<std::pair<int, int>> entries;
  for (size_t i = 0; i < couplings_.size(); ++i) {
    if (couplings_[i]->dense()) continue;
    couplings_[i]->pattern(entries);
    auto& columns = sparse_columns[i];
    columns.assign(offset_[i + 1] - offset_[i], {});
    for (auto [r, c] : entries) columns[static_cast<size_t>(r)].push_back(c);
  }

  // The (coupling, position) pairs at each local row, compressed by row.
  struct Incidence {
    std::uint32_t coupling, position;
  };
  std::vector<size_t> incidence_start(n_local + 1, 0);
  for (const PetscInt row : local_index_)
    if (row >= 0) ++incidence_start[static_cast<size_t>(row) + 1];
  for (size_t r = 0; r < n_local; ++r) incidence_start[r + 1] += incidence_start[r];
  std::vector<Incidence> incidences(incidence_start.back());
  {
    std::vector<size_t> next(incidence_start.begin(), incidence_start.end() - 1);
    for (size_t i = 0; i < couplings_.size(); ++i)
      for (size_t k = offset_[i]; k < offset_[i + 1]; ++k)
        if (const PetscInt row = local_index_[k]; row >= 0)
          incidences[next[static_cast<size_t>(row)]++] = {
              static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(k - offset_[i])};
  }

  // Each row's columns, marked by local index so that a column is listed once.
  std::vector<size_t> seen_in_row(n_local, n_local);
  std::vector<PetscInt> row_columns;
  for (size_t row = 0; row < n_local; ++row) {
    row_columns.clear();
    const auto add = [&](size_t k) {
      const PetscInt local = local_index_[k];
      if (local < 0 || seen_in_row[static_cast<size_t>(local)] == row) return;
      seen_in_row[static_cast<size_t>(local)] = row;
      row_columns.push_back(global_index_[k]);
    };
    for (size_t j = incidence_start[row]; j < incidence_start[row + 1]; ++j) {
      const Incidence& at = incidences[j];
      const size_t begin = offset_[at.coupling];
      if (couplings_[at.coupling]->dense()) {
        for (size_t k = begin; k < offset_[at.coupling + 1]; ++k) add(k);
      } else {
        for (int c : sparse_columns[at.coupling][at.position]) add(begin + static_cast<size_t>(c));
      }
    }
    fn(static_cast<PetscInt>(row), row_columns);
  }
}

namespace {

// Sends each ghost row's columns to the rank owning the row; returns, per owned row, the
// columns other ranks' couplings put there (global indices, in no order, maybe repeated).
std::vector<std::vector<PetscInt>> exchange_boundary_rows(
    MPI_Comm comm, const DofMap& dofs,
    const std::function<void(const std::function<void(PetscInt, std::vector<PetscInt>&)>&)>&
        visit) {
  const int size = mpi_size(comm);
  std::vector<PetscInt> owned_counts(static_cast<size_t>(size));
  const PetscInt n_owned = dofs.n_owned();
  MPI_Allgather(&n_owned, 1, MPIU_INT, owned_counts.data(), 1, MPIU_INT, comm);
  std::vector<PetscInt> range_start(static_cast<size_t>(size) + 1, 0);
  for (int r = 0; r < size; ++r) range_start[r + 1] = range_start[r] + owned_counts[r];

  // Per destination: [global row, count, columns...] for each of its rows.
  std::vector<std::vector<PetscInt>> out(static_cast<size_t>(size));
  visit([&](PetscInt local_row, std::vector<PetscInt>& columns) {
    if (local_row < n_owned || columns.empty()) return;
    const PetscInt row = dofs.ghosts()[static_cast<size_t>(local_row - n_owned)];
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

  std::vector<std::vector<PetscInt>> remote(static_cast<size_t>(n_owned));
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
  std::vector<std::vector<PetscInt>> remote;
  if (mpi_size(comm_) > 1)
    remote = exchange_boundary_rows(comm_, dofs_, [this](const auto& fn) { visit_pattern_rows(fn); });
  // Each owned row's columns: this rank's, merged with other ranks' where there are any.
  const auto visit_owned = [&](auto&& fn) {
    visit_pattern_rows([&](PetscInt row, std::vector<PetscInt>& columns) {
      if (row >= n) return;
      if (!remote.empty() && !remote[static_cast<size_t>(row)].empty()) {
        const auto& more = remote[static_cast<size_t>(row)];
        columns.insert(columns.end(), more.begin(), more.end());
        std::sort(columns.begin(), columns.end());
        columns.erase(std::unique(columns.begin(), columns.end()), columns.end());
      }
      fn(first + row, columns);
    });
  };

  std::vector<PetscInt> diagonal(static_cast<size_t>(n), 0), off_diagonal(static_cast<size_t>(n), 0);
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
