#include "catena/solvers/modal/exact_step.hpp"

#include <unsupported/Eigen/MatrixFunctions>

#include <algorithm>
#include <cmath>

#include "catena/core/error.hpp"

namespace catena::solvers {

ExactStep exact_step(const Eigen::MatrixXd& stiffness, const Eigen::MatrixXd& damping, double h) {
  const Eigen::Index n = stiffness.rows();
  CATENA_ASSERT(
      n > 0 && stiffness.cols() == n && damping.rows() == n && damping.cols() == n && h > 0.0,
      "exact_step: square matrices of one size and a positive step");
  // Time scale: the stiffest frequency, or 1/h for a system without stiffness.
  const double norm = stiffness.cwiseAbs().rowwise().sum().maxCoeff();
  const double omega = norm > 0.0 ? std::sqrt(norm) : 1.0 / h;
  const double H = omega * h;
  // Scaled first-order matrix: d/dτ [u, u̇/ω] = [[0, I], [−K'/ω², −C'/ω]] [u, u̇/ω] + [0, g/ω²].
  Eigen::MatrixXd W = Eigen::MatrixXd::Zero(6 * n, 6 * n);
  W.block(0, n, n, n).setIdentity();
  W.block(n, 0, n, n) = -stiffness / (omega * omega);
  W.block(n, n, n, n) = -damping / omega;
  W.block(0, 2 * n, 2 * n, 2 * n).setIdentity();
  W.block(2 * n, 4 * n, 2 * n, 2 * n).setIdentity();
  const Eigen::MatrixXd X = (W * H).exp();
  const Eigen::MatrixXd E = X.block(0, 0, 2 * n, 2 * n);
  const Eigen::MatrixXd Y1 = X.block(0, 2 * n, 2 * n, 2 * n);      // H φ1
  const Eigen::MatrixXd Y2 = X.block(0, 4 * n, 2 * n, 2 * n) / H;  // H φ2
  // Only the load's lower half [0, g/ω²] enters.
  const Eigen::MatrixXd P0 = (Y1 - Y2).block(0, n, 2 * n, n) / (omega * omega);
  const Eigen::MatrixXd P1 = Y2.block(0, n, 2 * n, n) / (omega * omega);
  ExactStep s;
  s.Euu = E.block(0, 0, n, n);
  s.Euv = E.block(0, n, n, n) / omega;
  s.Evu = E.block(n, 0, n, n) * omega;
  s.Evv = E.block(n, n, n, n);
  s.Gu0 = P0.topRows(n);
  s.Gu1 = P1.topRows(n);
  s.Gv0 = P0.bottomRows(n) * omega;
  s.Gv1 = P1.bottomRows(n) * omega;
  return s;
}

}  // namespace catena::solvers
