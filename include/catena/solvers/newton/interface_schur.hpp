#pragma once
// An exact parallel solve of a line's Newton matrix by its partition interface (a Schur
// complement): the rows a rank shares with another rank (its interface: rows with a
// column owned elsewhere, and the hubs — rows coupled to many other ranks' unknowns, a
// pantograph's head, whose contact pattern reaches the wire it crosses in the run) are
// split from the rest (its interior). The interior rows of different ranks never couple, so each
// rank factors its own interior block A_II with PETSc's LU (the fast solver of docs/performance.md,
// "Direct solver"; in place, without a copy); the interface's Schur complement S = A_ΓΓ − A_ΓI
// A_II⁻¹ A_IΓ is formed explicitly as a sparse matrix and factored on every rank. The rows of
// Lagrange multipliers marked on J (constraints_last_ordering.hpp) are interface rows too: no
// interior block holds a zero diagonal, and S is factored with them last. A line cut into P pieces
// has an interface of a few nodes per cut, each coupled to its neighbouring cuts only, so S is
// small and sparse and the solve is a direct one, independent of the rank count to round-off. Per
// solve, with W = A_II⁻¹ A_IΓ kept from the factorisation (its columns for the interface rows this
// rank's interior touches):
//   y = A_II⁻¹ b_I,   x_Γ = S⁻¹ (b_Γ − A_ΓI y),   x_I = y − W x_Γ,
// one interior solve per rank and one allreduce of the interface's values.
#include <petscksp.h>

namespace catena::solvers {

// Collective on J. Makes `ksp`'s preconditioner (a PCSHELL) the interface solve of J's
// pattern (J square, assembled with its full pattern; MPIAIJ on more than one rank; call
// once per KSP). It factors at every PCSetUp, i.e. whenever the operator's values changed
// (a changed nonzero pattern is an error). A pivot under PCLU's zero-pivot threshold
// (100 ε) in an interior block or in S (both factored without pivoting) is the PC's
// failure (PC_FACTOR_NUMERIC_ZEROPIVOT: the KSP reports KSP_DIVERGED_PC_FAILED and the
// solution is NaN), which the next successful factorisation clears. An error on one rank
// (a PETSc error in its interior factorisation) is thrown on every rank. Block solves
// (KSPMatSolve) go column by column. Returns the number of interface rows (all ranks).
long use_interface_schur(KSP ksp, Mat J);

}  // namespace catena::solvers
