#pragma once
// The Newton configuration shared by Catena's nonlinear solvers (statics, HHT, IRK stages):
// SNES newtonls with full steps (a residual-norm line search rejects good steps in stiff
// axial/bending problems; callers cut the load or time step instead), no divergence
// tolerance, KSPPREONLY with a direct factorisation (LDLᵀ when the Jacobian is symmetric,
// else LU; MUMPS with null-pivot detection unless `Pivoting` below allows PETSc's own),
// options prefix `prefix`, SNESSetFromOptions last.
#include <petscsnes.h>

#include <string>

#include "catena/assembly/petsc_handle.hpp"

namespace catena::solvers {

enum class JacobianSymmetry { symmetric, general };

// Whether the factorisation must pivot. MUMPS always does (threshold partial pivoting,
// null-pivot detection, any rank count). On one rank, PETSc's own LU with a
// nested-dissection ordering factors and solves the banded, ladder-like matrices of lines
// and catenaries 4–5 times faster than MUMPS (docs/performance.md, "Direct solver"), but
// it does not pivot: a zero pivot fails the factorisation (the Newton solve then fails and
// the caller cuts the step). `not_needed` is for matrices whose diagonal cannot vanish:
// the HHT Newton matrix M + c_C C + c_K K of a system without Lagrange multipliers (no
// zero diagonal block). On more than one rank such a matrix is solved by its partition
// interface instead (interface_schur.hpp: each rank's interior with PETSc's LU, the few
// interface rows' Schur complement redundantly), not by MUMPS. The options database still
// decides last (-<prefix>pc_type lu or -<prefix>pc_factor_mat_solver_type mumps: MUMPS).
// `required`: the matrix has zero diagonal rows (Lagrange multipliers), which only a
// pivoting factorisation gets past; the options may not choose PETSc's own LU for it
// (an input error naming the option: every step's factorisation would fail at its zero
// pivot, and the step be halved down to dt_min). `constraints_last`: the same matrix with
// its multiplier rows marked (constraints_last_ordering.hpp): on one rank PETSc's LU with
// the multipliers eliminated last, whose pivots are then the Schur complement's (the
// mechanism pantograph's EN 50318 run then costs 1.12 times the lumped one's instead of
// 1.5–2.5 with MUMPS; docs/performance.md); on more ranks the
// interface split with the multipliers among the interface rows (taken last in S); MUMPS
// when the options choose it.
enum class Pivoting { needed, not_needed, required, constraints_last };

// Logically collective on the SNES.
void configure_direct_newton(SNES snes, const std::string& prefix, JacobianSymmetry symmetry,
                             Pivoting pivoting = Pivoting::needed);

// Collective. A KSPPREONLY direct factorisation (LDLᵀ or LU; MUMPS with null-pivot
// detection, or PETSc's own on one rank when `pivoting` allows) with options prefix
// `prefix`, KSPSetFromOptions applied. With `split` (the matrix the KSP will factor, its
// pattern final) and on more than one rank, a matrix needing no pivoting is solved by the
// interface split of that pattern, as configure_direct_newton does (use_interface_split).
// Set further MUMPS defaults (e.g. enable_mumps_exact_inertia) before calling.
KspHandle create_direct_ksp(MPI_Comm comm, const std::string& prefix, JacobianSymmetry symmetry,
                            Pivoting pivoting = Pivoting::needed, Mat split = nullptr);

// Collective on the KSP. After a failed solve of a Pivoting::constraints_last matrix: if
// PETSc's LU met a zero pivot (dependent constraints, or an unknown that only a constraint
// holds, such as a slider's arc length on a straight path), the KSP factors with MUMPS, as
// for Pivoting::required, from now on, and a note says so; returns whether it switched
// (false for any other failure, or a package the options chose).
bool fall_back_to_pivoting(KSP ksp, const std::string& prefix, JacobianSymmetry symmetry);

// Collective on the KSP. Makes a KSP that factors without pivoting (PETSc's LU, or the
// interface split) factor with MUMPS, as for Pivoting::required, from now on, whatever made
// its solve fail; returns false (nothing changed) when it pivots already or the options
// chose its package.
bool switch_to_pivoting(KSP ksp, const std::string& prefix, JacobianSymmetry symmetry);

// Not collective. Whether a matrix on `comm` that needs no pivoting is solved by its
// partition interface (interface_schur.hpp) rather than factored whole: on more than one
// rank (MUMPS, which pivots, took over ten times as long per solve on EN 50318 at np 2;
// docs/performance.md, "Two ranks: the interface Schur solve"), unless the options choose another
// preconditioner or package (-<prefix>pc_type or -<prefix>pc_factor_mat_solver_type, e.g.
// `-hht_pc_type lu`: MUMPS).
bool use_interface_split(MPI_Comm comm, const std::string& prefix, Pivoting pivoting);

// Relative Newton update at which an iterate is converged to round-off (SNES stol).
inline constexpr double kNewtonStepTolerance = 1e-12;

}  // namespace catena::solvers
