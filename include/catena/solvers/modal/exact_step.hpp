#pragma once
// The exact step of a linear second-order system under a load linear in time over the step
// (the "piecewise exact" method of structural dynamics; Nigam & Jennings, "Calculation of
// response spectra from strong-motion earthquake records", BSSA 59, 1969):
//
//   ü + C' u̇ + K' u = g(t),   g linear on [0, h]   (C' = M⁻¹C, K' = M⁻¹K, g = M⁻¹ load)
//   u(h) = Euu u(0) + Euv u̇(0) + Gu0 g(0) + Gu1 g(h)
//   u̇(h) = Evu u(0) + Evv u̇(0) + Gv0 g(0) + Gv1 g(h)
//
// The matrices come from one matrix exponential (Van Loan's block form): with the first-order
// state y = [u, u̇], A its matrix and W = [[A, I, 0], [0, 0, I], [0, 0, 0]],
// exp(W h) holds e^{Ah}, h φ1(Ah) and h² φ2(Ah) (φ1(z) = (e^z − 1)/z, φ2(z) = (e^z − 1 − z)/z²),
// and y(h) = e^{Ah} y(0) + h (φ1 − φ2) b(0) + h φ2 b(h) for ẏ = A y + b, b = [0, g].
// Time is scaled by ω_s = √‖K'‖ first (u̇ by 1/ω_s), so that the exponential's entries are all
// O(ω_s h): a stiff mode's ω² ≈ 10⁵ s⁻² next to 1 would otherwise cost the small load terms
// (≈ h²) their digits. No period error, no amplitude error, for any h: the step is the exact
// solution of the system it is given.
#include <Eigen/Dense>

namespace catena::solvers {

struct ExactStep {
  Eigen::MatrixXd Euu, Euv, Evu, Evv;  // n × n
  Eigen::MatrixXd Gu0, Gu1, Gv0, Gv1;  // n × n, acting on g = M⁻¹ × load
};

// Not collective. K' = M⁻¹K and C' = M⁻¹C (n × n, any n ≥ 1), step h > 0 (s).
ExactStep exact_step(const Eigen::MatrixXd& stiffness, const Eigen::MatrixXd& damping, double h);

}  // namespace catena::solvers
