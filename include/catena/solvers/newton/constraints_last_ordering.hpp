#pragma once
// An elimination order for PETSc's LU (which does not pivot) of a Newton matrix with
// Lagrange multipliers, [A Gᵀ; G 0] up to row scaling: nested dissection of the whole
// pattern with the multiplier rows moved to the end. The unknowns they constrain are then
// eliminated first (A has mass in every row: its pivots never vanish), and each multiplier's
// pivot is an entry of the Schur complement −G A⁻¹ Gᵀ, nonzero for independent
// constraints — the block elimination of the saddle-point system, which needs no pivoting
// where A is positive definite or close to it (Benzi, Golub & Liesen, "Numerical solution of
// saddle point problems", Acta Numerica 14 (2005), §5). Fill stays small: the few
// multiplier rows and the separators they reach. Dependent constraints give a zero pivot,
// which PETSc reports as the factorisation's failure (the Newton solve fails).
#include <petscmat.h>

#include <vector>

namespace catena::solvers {

// Collective on J. Marks which of J's rows (the entries of `mask` that are nonzero, mask
// laid out as J's rows) are multipliers, for the ordering below (kept with J).
void mark_constraint_rows(Mat J, Vec mask);

// Not collective. This rank's rows of J marked by mark_constraint_rows (global numbers,
// ascending), or none.
std::vector<PetscInt> constraint_rows(Mat J);

// Not collective. Marks J's rows `rows` (this rank's, J's numbers) as multipliers.
void mark_constraint_rows(Mat J, const std::vector<PetscInt>& rows);

// Not collective. The ordering's name for PCFactorSetMatOrderingType (registered with
// PETSc on each call, so that a PETSc initialised again finds it). For sequential matrices
// marked by mark_constraint_rows; an unmarked matrix is the ordering's error.
const char* constraints_last_ordering();

}  // namespace catena::solvers
