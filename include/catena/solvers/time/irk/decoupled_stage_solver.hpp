#pragma once
// The decoupled (RADAU5-style) linear algebra of the implicit Runge–Kutta stage Newton
// (Hairer & Wanner II, Sect. IV.8, in the K-form of docs/integrators.md).
//
// Simplified Newton's stage matrix has Kronecker form (stage-major notation; the vectors
// are interleaved DOF-major, entry s·g + i for DOF g and stage i):
//   J = P (I ⊗ M′ + h A ⊗ C + h² A² ⊗ K),
// M′ = M (+ Gᵀ with constraints), K = ∂f/∂q (+ G), C = ∂f/∂v, and P = I ⊗ diag(d) the
// scaling of the constraint rows by m̄/h² (d = 1 elsewhere; none without constraints).
// With A = T D T⁻¹ (tableau_decomposition.hpp), A² = T D² T⁻¹ and
//   J = (T ⊗ I) P (I ⊗ M′ + h D ⊗ C + h² D² ⊗ K) (T⁻¹ ⊗ I),
// so J y = r is solved as z = (T⁻¹ ⊗ I) r, one solve per block of D, y = (T ⊗ I) w:
//   real λ:             (M′ + hλ C + h²λ² K) w = z                                (n × n)
//   pair α ± iβ:        [ R  −S ] [w₁]   [z₁]    R = M′ + hα C + h²(α² − β²) K
//                       [ S   R ] [w₂] = [z₂],   S = hβ C + 2h²αβ K               (2n × 2n)
// (D's pair block is [α −β; β α]; its square is [α²−β², −2αβ; 2αβ, α²−β²]). The 2n system
// is the complex solve (R + iS)(w₁ + iw₂) = z₁ + iz₂ written in real arithmetic, assembled
// interleaved like the stage matrix (BlockMatrix with two blocks: exact preallocation,
// bandwidth doubled, not grown by n). Every block is factored by its own MUMPS LU. For
// s = 3: one n and one 2n factorisation instead of one 3n; for the banded matrices of a
// line, roughly 5/9 of the factor's entries and 1/3 of its flops.
//
// PETSc fit: SNES keeps its Newton loop; its operator is a MATSHELL applying J (for
// Krylov methods and checks; the direct solve never multiplies by it), and its KSP is
// KSPPREONLY with this PCSHELL, whose setup factors the blocks and whose apply transforms,
// solves and transforms back. Block b's KSP has the options prefix <prefix>block<b>_
// (e.g. -irk_block1_mat_mumps_icntl_14 30).
//
// Failures are reported, never thrown: a block factorisation or solve that fails (MUMPS
// INFOG(1) < 0, a null pivot, a KSP that did not converge) sets the PC's failed reason and
// an infinite result, so SNES stops with a linear-solve failure; failure() says which block
// and why.
#include <petscksp.h>

#include <memory>
#include <string>

#include "catena/assembly/petsc_call.hpp"
#include "catena/assembly/petsc_handle.hpp"
#include "catena/solvers/newton/direct_newton.hpp"
#include "catena/solvers/time/irk/tableau_decomposition.hpp"

namespace catena::solvers {

// The stage matrix's parts; pointers owned by the caller, kept valid while the solver
// uses them (until the next assemble()).
struct StageMatrixParts {
  Mat K = nullptr;          // ∂R/∂q, n × n
  Mat C = nullptr;          // ∂R/∂v, n × n (same pattern)
  Mat M = nullptr;          // the δ_ij part (M, or M + Gᵀ), same pattern
  Vec row_scale = nullptr;  // d (null: none), laid out as the DOFs
  double h = 0.0;           // s
};

class DecoupledStageSolver {
 public:
  // Collective. pattern: an assembled n × n MPIAIJ matrix with K's, C's and M's pattern.
  // A, A2: the tableau's A and A² (for the shell operator's product, which must equal the
  // coupled stage matrix's), A = T D T⁻¹ by `form`. Block KSPs: prefix + "block<b>_",
  // factored with `pivoting` (direct_newton.hpp; `required` with multipliers).
  DecoupledStageSolver(Mat pattern, const Eigen::MatrixXd& A, const Eigen::MatrixXd& A2,
                       const TableauDecomposition& form, const std::string& prefix,
                       Pivoting pivoting = Pivoting::needed);
  ~DecoupledStageSolver();
  DecoupledStageSolver(const DecoupledStageSolver&) = delete;
  DecoupledStageSolver& operator=(const DecoupledStageSolver&) = delete;

  // The s·n MATSHELL operator J, for SNESSetJacobian.
  Mat operator_matrix() const;
  // Logically collective. Makes ksp's PC this solver (PCSHELL; the KSP type is not
  // touched). Exceptions inside the PC and operator callbacks are stored in `guard` (the
  // SNES owner's, which rethrows them after the solve).
  void install(KSP ksp, CallbackGuard& guard);
  // Collective. Builds the block matrices from parts and marks the operator changed, so
  // that the PC factors them at its next setup (not here).
  void assemble(const StageMatrixParts& parts);

  // Collective. The KSP of the real block with eigenvalue λ (to 1e-14 relative), factored
  // for the last assemble(): the filter matrix M′ + hλ C + h²λ² K for other solves with it
  // (Radau IIA's error estimate, λ = γ0). Null if there is no such block or its
  // factorisation failed.
  KSP real_block(double lambda);

  // Not collective. The last failure (empty after a successful setup and apply).
  const std::string& failure() const;
  // Collective. y = J⁻¹ r with the current factorisations (what the PC applies); returns
  // false on failure (see failure()).
  bool solve(Vec r, Vec y);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace catena::solvers
