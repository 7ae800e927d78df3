#pragma once
// Long-double building blocks of the Butcher tableaus (butcher_tableau.cpp): roots of
// Legendre-type polynomials for the nodes, and the collocation integrals for A and b.
// Everything is computed in long double (64-bit mantissa on x86-64) so that the rounded
// double coefficients are accurate to about one unit in the last place.
#include <Eigen/Dense>
#include <functional>

namespace catena::solvers::detail {

using Real = long double;
using VectorL = Eigen::Matrix<Real, Eigen::Dynamic, 1>;
using MatrixL = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>;

// The root of f in [lo, hi], where f(lo) and f(hi) differ in sign, by bisection down to
// adjacent long doubles: robust, and at ~64 halvings per root cheap enough.
Real bracketed_root(const std::function<Real(Real)>& f, Real lo, Real hi);

// Nodes on [0, 1], increasing (HW II, Sect. IV.5):
//   Gauss: the s roots of the shifted Legendre polynomial P_s(2x − 1);
//   Radau IIA: the roots of P_s(2x − 1) − P_{s−1}(2x − 1), the last being x = 1;
//   Lobatto: 0, 1 and the s − 2 roots of P'_{s−1}(2x − 1).
VectorL gauss_nodes(int s);
VectorL radau_right_nodes(int s);
VectorL lobatto_nodes(int s);

// ℓ_j(x) for the Lagrange basis on the given nodes.
VectorL lagrange_values(const VectorL& nodes, Real x);
// ∫_0^x ℓ_j(τ) dτ, j = 1..n, by a Gauss–Legendre rule that is exact for degree n − 1.
VectorL lagrange_integrals(const VectorL& nodes, Real x);

// The collocation method on nodes c: a_ij = ∫_0^{c_i} ℓ_j (⇔ C(s)), b_j = ∫_0^1 ℓ_j (⇔ B(s)).
MatrixL collocation_matrix(const VectorL& c);
VectorL quadrature_weights(const VectorL& c);

// Lobatto IIIC (Chipman 1971; HW IV.5): a_i1 = b_1 for every i, and C(s − 1) for the rest.
MatrixL lobatto_iiic_matrix(const VectorL& c, const VectorL& b);

}  // namespace catena::solvers::detail
