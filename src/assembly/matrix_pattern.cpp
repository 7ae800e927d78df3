// SecondOrderSystem::create_matrix: a matrix holding the union of the couplings' patterns
// over this rank's rows (part of the class: include/catena/assembly/second_order_system.hpp).
//
// Each owned row visits the couplings that touch it and marks the columns it has seen (one
// integer per local column), twice: once to count the row's entries for the preallocation,
// once to insert them as zeros. Why not PETSc's MATPREALLOCATOR: a dense coupling of n DOFs
// names n² pairs, most shared with its neighbours, and the preallocator hashes every one
// (about 7 % of the moving-load benchmark's process); why not compressed rows handed to
// PETSc whole: they held a second copy of the pattern while the matrix was allocated,
// which raised the run's peak memory (docs/performance.md). Here the extra memory is one
// row and the row → coupling incidence.
#include <algorithm>
#include <cstdint>

#include "catena/assembly/petsc_call.hpp"
#include "catena/assembly/second_order_system.hpp"

namespace catena::assembly {

template <class Fn>
void SecondOrderSystem::visit_pattern_rows(Fn&& fn) const {
  const PetscInt n_rows = dofs_.n_owned(), first = dofs_.first_owned();
  const auto owned_row = [&](PetscInt global) {
    return global >= first && global < first + n_rows ? global - first : PetscInt{-1};
  };

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

  // The (coupling, position) pairs at each owned row, compressed by row.
  struct Incidence {
    std::uint32_t coupling, position;
  };
  std::vector<PetscInt> incidence_start(static_cast<size_t>(n_rows) + 1, 0);
  for (size_t k = 0; k < global_index_.size(); ++k)
    if (const PetscInt row = owned_row(global_index_[k]); row >= 0)
      ++incidence_start[static_cast<size_t>(row) + 1];
  for (size_t r = 0; r < static_cast<size_t>(n_rows); ++r)
    incidence_start[r + 1] += incidence_start[r];
  std::vector<Incidence> incidences(static_cast<size_t>(incidence_start.back()));
  {
    std::vector<PetscInt> next(incidence_start.begin(), incidence_start.end() - 1);
    for (size_t i = 0; i < couplings_.size(); ++i)
      for (size_t k = offset_[i]; k < offset_[i + 1]; ++k)
        if (const PetscInt row = owned_row(global_index_[k]); row >= 0)
          incidences[static_cast<size_t>(next[static_cast<size_t>(row)]++)] = {
              static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(k - offset_[i])};
  }

  // Each row's columns, marked by ghosted local index so that a column is listed once.
  std::vector<PetscInt> seen_in_row(
      static_cast<size_t>(dofs_.n_owned()) + dofs_.ghosts().size(), -1);
  std::vector<PetscInt> row_columns;
  for (PetscInt row = 0; row < n_rows; ++row) {
    row_columns.clear();
    const auto add = [&](size_t k) {
      const PetscInt local = local_index_[k];
      if (local < 0 || seen_in_row[static_cast<size_t>(local)] == row) return;
      seen_in_row[static_cast<size_t>(local)] = row;
      row_columns.push_back(global_index_[k]);
    };
    for (PetscInt j = incidence_start[static_cast<size_t>(row)];
         j < incidence_start[static_cast<size_t>(row) + 1]; ++j) {
      const Incidence& at = incidences[static_cast<size_t>(j)];
      const size_t begin = offset_[at.coupling];
      if (couplings_[at.coupling]->dense()) {
        for (size_t k = begin; k < offset_[at.coupling + 1]; ++k) add(k);
      } else {
        for (int c : sparse_columns[at.coupling][at.position]) add(begin + static_cast<size_t>(c));
      }
    }
    fn(first + row, row_columns);
  }
}

MatHandle SecondOrderSystem::create_matrix() const {
  const PetscInt n = dofs_.n_owned(), N = dofs_.n_global(), first = dofs_.first_owned();
  std::vector<PetscInt> diagonal(static_cast<size_t>(n), 0), off_diagonal(static_cast<size_t>(n), 0);
  size_t longest = 0;
  visit_pattern_rows([&](PetscInt row, const std::vector<PetscInt>& columns) {
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
  visit_pattern_rows([&](PetscInt row, std::vector<PetscInt>& columns) {
    std::sort(columns.begin(), columns.end());
    CATENA_PETSC(MatSetValues(J.get(), 1, &row, static_cast<PetscInt>(columns.size()),
                              columns.data(), zeros.data(), INSERT_VALUES));
  });
  CATENA_PETSC(MatAssemblyBegin(J.get(), MAT_FINAL_ASSEMBLY));
  CATENA_PETSC(MatAssemblyEnd(J.get(), MAT_FINAL_ASSEMBLY));
  return J;
}

}  // namespace catena::assembly
