#pragma once
// The real block-diagonal form of a Butcher matrix, A = T D T⁻¹, behind the decoupled
// (RADAU5-style) stage solve of the implicit Runge–Kutta integrator (Hairer & Wanner II,
// Sect. IV.8; docs/integrators.md, "Decoupled stage solve").
//
// D holds one 1 × 1 block λ per real eigenvalue and one 2 × 2 block
//     [ α  −β ]
//     [ β   α ]          (β > 0)
// per complex pair α ± iβ. T's columns: the unit eigenvector of a real λ; for a pair, the
// real part u and minus the imaginary part −w of the eigenvector v = u + iw of α + iβ,
// after the phase rotation that makes u ⊥ w (the best-conditioned real pair), so that
// A u = α u + β(−w) and A(−w) = −β u + α(−w). Real eigenvalues come first, then the pairs,
// each group by increasing real part.
//
// Computed in long double from the double A (exactly representable there): Eigen's real
// eigensolver, T rounded to double, T⁻¹ the long-double inverse of that rounded T, and D
// = T⁻¹ A T in long double with the off-block entries checked to be round-off and dropped.
// So T D T⁻¹ reproduces the A the coupled stage matrix uses to a few ulps.
//
// Refused (no decomposition; the coupled stage matrix serves): a zero eigenvalue (Lobatto
// IIIA's explicit first stage: A singular), repeated or nearly repeated eigenvalues (SDIRK's
// A has the triple eigenvalue γ and is not diagonalisable), or an ill-conditioned T.
//
// Not collective: no MPI, no PETSc.
#include <Eigen/Dense>
#include <optional>
#include <string>
#include <vector>

namespace catena::solvers {

struct EigenBlock {
  int offset = 0;  // first row/column of the block in D (and column of T)
  int size = 1;    // 1: real eigenvalue; 2: complex pair
};

struct TableauDecomposition {
  Eigen::MatrixXd T, T_inv;  // s × s, T_inv = T⁻¹ to rounding
  Eigen::MatrixXd D;         // s × s real block diagonal, blocks as above
  std::vector<EigenBlock> blocks;
  double condition = 0.0;  // ‖T‖₂ ‖T⁻¹‖₂
};

// Not collective. The decomposition of the s × s matrix A, or nothing with the reason in
// *why_not (when given). s ≤ 5 in practice; any s works.
std::optional<TableauDecomposition> decompose_butcher_matrix(const Eigen::MatrixXd& A,
                                                             std::string* why_not = nullptr);

}  // namespace catena::solvers
