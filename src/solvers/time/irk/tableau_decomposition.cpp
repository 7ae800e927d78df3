#include "catena/solvers/time/irk/tableau_decomposition.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <complex>
#include <sstream>

namespace catena::solvers {
namespace {

using Real = long double;
using MatrixL = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>;
using VectorCL = Eigen::Matrix<std::complex<Real>, Eigen::Dynamic, 1>;

// Thresholds relative to ‖A‖ (entries of O(1) for every tableau here). Real Butcher
// eigenvalues are either clearly real or clearly complex, and clearly apart (the closest
// pair of any supported tableau is 6.4e-2 apart, Gauss 5); a defective triple eigenvalue such as
// SDIRK's splits by about ε^{1/3} ≈ 1e-6 in long double, far below kSeparation.
constexpr Real kImaginary = 1e-12L;
constexpr Real kZero = 1e-10L;
constexpr Real kSeparation = 1e-4L;
constexpr Real kOffBlock = 1e-14L;
constexpr double kMaxCondition = 1e6;

bool refuse(std::string* why_not, const std::string& why) {
  if (why_not) *why_not = why;
  return false;
}

double two_norm_condition(const Eigen::MatrixXd& T, const Eigen::MatrixXd& T_inv) {
  const Eigen::JacobiSVD<Eigen::MatrixXd> a(T), b(T_inv);
  return a.singularValues()(0) * b.singularValues()(0);
}

}  // namespace

std::optional<TableauDecomposition> decompose_butcher_matrix(const Eigen::MatrixXd& A,
                                                             std::string* why_not) {
  const auto s = static_cast<int>(A.rows());
  const MatrixL a = A.cast<Real>();
  const Real scale = std::max(a.cwiseAbs().maxCoeff(), Real(1e-300L));
  const Eigen::EigenSolver<MatrixL> solver(a, true);
  if (solver.info() != Eigen::Success) {
    refuse(why_not, "the eigenvalue iteration did not converge");
    return std::nullopt;
  }
  const auto values = solver.eigenvalues();
  const auto vectors = solver.eigenvectors();
  for (int i = 0; i < s; ++i) {
    if (std::abs(values(i)) <= kZero * scale) {
      refuse(why_not, "A is singular (a zero eigenvalue: an explicit stage)");
      return std::nullopt;
    }
    for (int j = 0; j < i; ++j)
      if (std::abs(values(i) - values(j)) <= kSeparation * scale) {
        refuse(why_not,
               "A has a repeated eigenvalue (not diagonalisable by a well-"
               "conditioned T)");
        return std::nullopt;
      }
  }
  // Order: real eigenvalues, then pairs (the member with β > 0), by real part.
  std::vector<int> real, pairs;
  for (int i = 0; i < s; ++i) {
    const Real im = values(i).imag();
    if (std::abs(im) <= kImaginary * scale)
      real.push_back(i);
    else if (im > 0)
      pairs.push_back(i);
  }
  const auto by_real_part = [&](int i, int j) { return values(i).real() < values(j).real(); };
  std::sort(real.begin(), real.end(), by_real_part);
  std::sort(pairs.begin(), pairs.end(), by_real_part);

  TableauDecomposition out;
  MatrixL T(s, s);
  int column = 0;
  for (int i : real) {
    Eigen::Matrix<Real, Eigen::Dynamic, 1> u = vectors.col(i).real();
    T.col(column) = u / u.norm();
    out.blocks.push_back({column, 1});
    ++column;
  }
  for (int i : pairs) {
    VectorCL v = vectors.col(i);
    // Rotate the phase, v ← e^{iφ} v, so that Re v ⊥ Im v: with u = Re v, w = Im v,
    // tan 2φ = −2u·w / (u·u − w·w).
    const Eigen::Matrix<Real, Eigen::Dynamic, 1> u0 = v.real(), w0 = v.imag();
    const Real phi = Real(0.5L) * std::atan2(Real(-2) * u0.dot(w0), u0.dot(u0) - w0.dot(w0));
    v *= std::polar(Real(1), phi);
    v /= v.norm();
    T.col(column) = v.real();
    T.col(column + 1) = -v.imag();
    out.blocks.push_back({column, 2});
    column += 2;
  }
  if (column != s) {
    refuse(why_not, "the eigenvalues do not split into real ones and conjugate pairs");
    return std::nullopt;
  }
  out.T = T.cast<double>();
  const MatrixL T_rounded = out.T.cast<Real>();
  const Eigen::FullPivLU<MatrixL> lu(T_rounded);
  if (!lu.isInvertible()) {
    refuse(why_not, "the eigenvector matrix T is singular");
    return std::nullopt;
  }
  const MatrixL T_inv = lu.inverse();
  out.T_inv = T_inv.cast<double>();
  out.condition = two_norm_condition(out.T, out.T_inv);
  if (!(out.condition <= kMaxCondition)) {
    std::ostringstream os;
    os << "the eigenvector matrix T is ill-conditioned (condition " << out.condition << ")";
    refuse(why_not, os.str());
    return std::nullopt;
  }
  // D = T⁻¹ A T with the rounded T: its block diagonal is what reproduces A.
  const MatrixL D = T_inv * a * T_rounded;
  out.D = Eigen::MatrixXd::Zero(s, s);
  for (int i = 0; i < s; ++i)
    for (int j = 0; j < s; ++j) {
      bool in_block = false;
      for (const EigenBlock& b : out.blocks)
        in_block = in_block || (i >= b.offset && i < b.offset + b.size && j >= b.offset &&
                                j < b.offset + b.size);
      if (in_block) {
        out.D(i, j) = static_cast<double>(D(i, j));
      } else if (std::abs(D(i, j)) > kOffBlock * scale) {
        std::ostringstream os;
        os << "T⁻¹AT is not block diagonal (entry (" << i << ", " << j
           << ") = " << static_cast<double>(D(i, j)) << ")";
        refuse(why_not, os.str());
        return std::nullopt;
      }
    }
  return out;
}

}  // namespace catena::solvers
