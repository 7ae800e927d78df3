#include "catena/solvers/time/algebraic_part.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "catena/assembly/petsc_call.hpp"

namespace catena::solvers {
namespace {

// Calls fn(i) for every local index whose mask entry is set.
template <class Fn>
void for_each_algebraic(Vec mask, Fn&& fn) {
  PetscInt n = 0;
  const PetscScalar* m = nullptr;
  CATENA_PETSC(VecGetLocalSize(mask, &n));
  CATENA_PETSC(VecGetArrayRead(mask, &m));
  for (PetscInt i = 0; i < n; ++i)
    if (m[i] != 0.0) fn(i);
  CATENA_PETSC(VecRestoreArrayRead(mask, &m));
}

}  // namespace

AlgebraicPart::AlgebraicPart(assembly::SecondOrderSystem& system, Mat mass)
    : active_(system.has_constraints()) {
  if (!active_) return;
  mask_ = system.create_vector();
  system.algebraic_mask(mask_.get());
  VecHandle diagonal = system.create_vector();
  CATENA_PETSC(MatGetDiagonal(mass, diagonal.get()));
  PetscScalar total = 0.0, n_algebraic = 0.0;
  PetscInt n = 0;
  CATENA_PETSC(VecSum(diagonal.get(), &total));  // multiplier rows of M are zero
  CATENA_PETSC(VecSum(mask_.get(), &n_algebraic));
  CATENA_PETSC(VecGetSize(diagonal.get(), &n));
  const double nodal = static_cast<double>(n) - n_algebraic;
  mass_scale_ = nodal > 0.0 && total > 0.0 ? total / nodal : 1.0;
}

double AlgebraicPart::residual_floor(double coefficient, Vec q) const {
  if (!active_) return 0.0;
  // max |q| over the nodal slots (positions dominate: slopes are of order one).
  PetscInt n = 0;
  const PetscScalar *x = nullptr, *m = nullptr;
  CATENA_PETSC(VecGetLocalSize(q, &n));
  CATENA_PETSC(VecGetArrayRead(q, &x));
  CATENA_PETSC(VecGetArrayRead(mask_.get(), &m));
  double local = 0.0, global = 0.0;
  for (PetscInt i = 0; i < n; ++i)
    if (m[i] == 0.0) local = std::max(local, std::abs(x[i]));
  CATENA_PETSC(VecRestoreArrayRead(mask_.get(), &m));
  CATENA_PETSC(VecRestoreArrayRead(q, &x));
  MPI_Comm comm = PETSC_COMM_SELF;
  CATENA_PETSC(PetscObjectGetComm(reinterpret_cast<PetscObject>(q), &comm));
  MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_MAX, comm);
  PetscScalar rows = 0.0;
  CATENA_PETSC(VecSum(mask_.get(), &rows));
  constexpr double eps = std::numeric_limits<double>::epsilon();
  return mass_scale_ / coefficient * 8.0 * eps * std::max(global, 1.0) * std::sqrt(rows);
}

std::function<double(Vec)> AlgebraicPart::residual_measure(double atol, double floor,
                                                           int blocks) const {
  if (!active_ || !(floor > 0.0)) return {};
  const double weight = atol / (atol + floor);
  return [this, weight, blocks](Vec r) {
    PetscInt n = 0;
    const PetscScalar *x = nullptr, *m = nullptr;
    PetscInt n_r = 0;
    CATENA_PETSC(VecGetLocalSize(mask_.get(), &n));
    CATENA_PETSC(VecGetLocalSize(r, &n_r));
    CATENA_ASSERT(n_r == blocks * n, "AlgebraicPart::residual_measure: residual of another layout");
    CATENA_PETSC(VecGetArrayRead(r, &x));
    CATENA_PETSC(VecGetArrayRead(mask_.get(), &m));
    double local[2] = {0.0, 0.0}, global[2] = {0.0, 0.0};  // nodal, constraint rows
    for (PetscInt i = 0; i < n; ++i)
      for (int b = 0; b < blocks; ++b) {
        const double e = x[blocks * i + b];
        local[m[i] != 0.0 ? 1 : 0] += e * e;
      }
    CATENA_PETSC(VecRestoreArrayRead(mask_.get(), &m));
    CATENA_PETSC(VecRestoreArrayRead(r, &x));
    MPI_Comm comm = PETSC_COMM_SELF;
    CATENA_PETSC(PetscObjectGetComm(reinterpret_cast<PetscObject>(r), &comm));
    MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_SUM, comm);
    return std::sqrt(global[0] + weight * weight * global[1]);
  };
}

void AlgebraicPart::take_algebraic(Vec target, Vec source) const {
  if (!active_) return;
  PetscScalar* t = nullptr;
  const PetscScalar* s = nullptr;
  CATENA_PETSC(VecGetArray(target, &t));
  CATENA_PETSC(VecGetArrayRead(source, &s));
  for_each_algebraic(mask_.get(), [&](PetscInt i) { t[i] = s[i]; });
  CATENA_PETSC(VecRestoreArrayRead(source, &s));
  CATENA_PETSC(VecRestoreArray(target, &t));
}

void AlgebraicPart::zero_algebraic(Vec x) const { scale_rows(x, 0.0); }

void AlgebraicPart::scale_rows(Vec r, double factor) const {
  if (!active_) return;
  PetscScalar* a = nullptr;
  CATENA_PETSC(VecGetArray(r, &a));
  for_each_algebraic(mask_.get(), [&](PetscInt i) { a[i] *= factor; });
  CATENA_PETSC(VecRestoreArray(r, &a));
}

void AlgebraicPart::scale_rows(Mat J, double factor, int blocks) {
  if (!active_) return;
  if (blocks != row_scale_blocks_ || factor != row_scale_factor_) {
    // The diagonal: 1 on nodal rows, factor on multiplier rows; for the stage matrix
    // (row s·g + i for DOF g, stage i) each DOF's entry repeated `blocks` times.
    PetscInt n_local = 0;
    CATENA_PETSC(VecGetLocalSize(mask_.get(), &n_local));
    row_scale_.reset();
    CATENA_PETSC(MatCreateVecs(J, nullptr, row_scale_.out()));
    PetscScalar* d = nullptr;
    const PetscScalar* m = nullptr;
    CATENA_PETSC(VecGetArray(row_scale_.get(), &d));
    CATENA_PETSC(VecGetArrayRead(mask_.get(), &m));
    for (PetscInt i = 0; i < n_local; ++i)
      for (int b = 0; b < blocks; ++b) d[blocks * i + b] = m[i] != 0.0 ? factor : 1.0;
    CATENA_PETSC(VecRestoreArrayRead(mask_.get(), &m));
    CATENA_PETSC(VecRestoreArray(row_scale_.get(), &d));
    row_scale_blocks_ = blocks;
    row_scale_factor_ = factor;
  }
  CATENA_PETSC(MatDiagonalScale(J, row_scale_.get(), nullptr));
}

}  // namespace catena::solvers
