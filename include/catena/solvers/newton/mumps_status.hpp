#pragma once
// MUMPS status after a factorisation. KSPPREONLY never reports a failed factorisation by
// itself, so solvers read INFOG(1) (error flag), INFOG(2) (its detail) and INFOG(28) (null
// pivots found with ICNTL(24) = 1) after every solve.
#include <petscksp.h>

#include <string>

namespace catena::solvers {

struct MumpsStatus {
  bool is_mumps = false;   // false: another solver was chosen on the command line
  bool symmetric = false;  // LDLᵀ (PCCHOLESKY): negative_pivots is the inertia
  long infog1 = 0, infog2 = 0, null_pivots = 0, negative_pivots = 0;
};

// Logically collective (same values on every rank). Call only after the KSP has factored.
MumpsStatus mumps_status(KSP ksp);

// The outcome of a direct solver's (KSPPREONLY with LU or Cholesky) factorisation or solve:
// the KSP's reason (still "iterating" after a KSPSetUp alone), the preconditioner's failure
// (PETSc's LU or the interface Schur solve meeting a zero pivot: after a KSPSetUp alone,
// only it tells) and MUMPS's status. A failure is a negative KSP reason, a failed
// preconditioner, a negative INFOG(1) or any null pivot (ICNTL(24) = 1 lets MUMPS go on
// past them, and the solution is then arbitrary along the null space).
struct DirectSolveStatus {
  KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
  PCFailedReason preconditioner = PC_NOERROR;
  MumpsStatus mumps;
  bool failed() const {
    return reason < 0 || preconditioner != PC_NOERROR || mumps.infog1 < 0 || mumps.null_pivots > 0;
  }
  // "KSP reason R, MUMPS INFOG(1) = a, INFOG(2) = b, n null pivots" (MUMPS parts only when
  // MUMPS is the solver).
  std::string describe() const;
};

// Logically collective (the preconditioner's failure is the same on every rank for the
// factorisations Catena makes: MUMPS, PETSc's LU on one rank, the interface Schur solve,
// which agrees its outcome). Call after KSPSetUp or KSPSolve of a direct solver.
DirectSolveStatus direct_solve_status(KSP ksp);

// Logically collective. If `status` is MUMPS running out of its workspace (INFOG(1) = −8,
// −9, −14, −17 or −20: its estimate from the analysis fell short, as delayed pivots of a
// saddle-point matrix make it, e.g. a small constrained system on three ranks), raises the
// margin MUMPS adds to the estimate (ICNTL(14), 20 % by default) to twice its value, at
// least +100 % (on a new factor of ksp's PC, which keeps it for its later factorisations),
// so that the next KSPSetUp or KSPSolve analyses and factors again. Returns whether it did (false:
// another failure, or the margin is at its cap of 1600 %).
bool enlarge_mumps_workspace(KSP ksp, const DirectSolveStatus& status);

// Not collective. Turns on MUMPS null-pivot detection (ICNTL(24) = 1) for the solver with
// options prefix `prefix`, unless the user set it on the command line.
void enable_mumps_null_pivot_detection(const std::string& prefix);

// Not collective. Makes MUMPS's negative-pivot count (INFOG(12)) exact in parallel
// (ICNTL(13) = 1: no ScaLAPACK on the root front, whose pivots INFOG(12) would not count)
// for the solver with options prefix `prefix`, unless the user set it.
void enable_mumps_exact_inertia(const std::string& prefix);

// Not collective. Makes MUMPS compute its row and column scaling from each matrix it
// factors (ICNTL(8) = 7, iterative scaling at factorisation) for the solver with options
// prefix `prefix`, unless the user set it. By default (ICNTL(8) = 77) MUMPS may compute the
// scaling of a symmetric indefinite matrix in its analysis, from the first matrix's
// values, and PETSc analyses once per nonzero pattern: matrices that change in kind after
// the first keep a scaling that no longer fits. The static load path with rigid bodies
// does so: its first tangent is that of the unloaded structure, where a body's rotations
// have no stiffness at all (a pendulum hung 5 cm below its hinge came out with 22 null
// pivots of 23 at full load, and a crane's Newton stalled). In the options database, as
// the other defaults here: for a prefix whose every solver wants it.
void scale_mumps_at_each_factorisation(const std::string& prefix);

// Collective on ksp, whose operators must be set. The same for ksp alone, on its factor
// (made now, with `prefix` as its options prefix, and kept for the PC's later
// factorisations), for a prefix whose other solvers do not want it: Newton's static solve
// only when the scene has rigid bodies.
void scale_mumps_factor_at_each_factorisation(KSP ksp, const std::string& prefix);

// Not collective. For a factorisation read only for its statistics (the inertia INFOG(12),
// the null pivots INFOG(28)), never solved with: MUMPS discards the factors as it computes
// them (ICNTL(31) = 1), so they take no memory beside another solver's (the static
// stability check beside Newton's factors: the 10 km line's static peak 420 -> 388 MiB at
// np 1, 318 -> 289 MiB at np 2), unless the user set it.
void discard_mumps_factors(const std::string& prefix);

}  // namespace catena::solvers
