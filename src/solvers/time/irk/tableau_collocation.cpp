#include "tableau_collocation.hpp"

#include <cmath>
#include <utility>
#include <vector>

#include "catena/core/error.hpp"

namespace catena::solvers::detail {
namespace {

// (P_n(y), P_{n−1}(y)) by the three-term recurrence (k + 1) P_{k+1} = (2k + 1) y P_k − k P_{k−1},
// which is stable on [−1, 1].
std::pair<Real, Real> legendre(int n, Real y) {
  Real p = 1, p_prev = 0;
  for (int k = 0; k < n; ++k) {
    const Real next = (static_cast<Real>(2 * k + 1) * y * p - static_cast<Real>(k) * p_prev) /
                      static_cast<Real>(k + 1);
    p_prev = p;
    p = next;
  }
  return {p, p_prev};
}

// P'_n(y) = n (y P_n − P_{n−1}) / (y² − 1), valid for |y| < 1 (all nodes used here).
Real legendre_derivative(int n, Real y) {
  const auto [p, p_prev] = legendre(n, y);
  return static_cast<Real>(n) * (y * p - p_prev) / (y * y - 1);
}

// All roots of f in the open interval (−1, 1). Every node polynomial here has only simple
// roots at least 0.1 apart for s ≤ 6, so a grid of spacing 0.002 separates them; a root
// falling exactly on a grid point (y = 0 for odd Gauss) is taken as it is.
std::vector<Real> interior_roots(const std::function<Real(Real)>& f, int n_expected) {
  constexpr int n_grid = 1000;
  std::vector<Real> roots;
  Real y_prev = -1 + Real{2} / n_grid, f_prev = f(y_prev);
  if (f_prev == 0) roots.push_back(y_prev);
  for (int k = 2; k < n_grid; ++k) {
    const Real y = -1 + Real{2} * k / n_grid, fy = f(y);
    if (fy == 0) {
      roots.push_back(y);
    } else if ((f_prev < 0 && fy > 0) || (f_prev > 0 && fy < 0)) {
      roots.push_back(bracketed_root(f, y_prev, y));
    }
    y_prev = y;
    f_prev = fy;
  }
  CATENA_ASSERT(static_cast<int>(roots.size()) == n_expected, "node polynomial: lost a root");
  (void)n_expected;
  return roots;
}

// y ∈ [−1, 1] → x ∈ [0, 1]. Symmetric node sets are symmetrised first, so that
// c_i + c_{s+1−i} = 1 holds to rounding.
VectorL to_unit_interval(std::vector<Real> y, bool symmetric) {
  const int n = static_cast<int>(y.size());
  if (symmetric) {
    for (int i = 0; i < n / 2; ++i) {
      const Real m = (y[i] - y[n - 1 - i]) / 2;
      y[i] = m;
      y[n - 1 - i] = -m;
    }
    if (n % 2 == 1) y[n / 2] = 0;
  }
  VectorL x(n);
  for (int i = 0; i < n; ++i) x(i) = (1 + y[i]) / 2;
  return x;
}

struct GaussRule {
  std::vector<Real> y, w;  // on [−1, 1]
};

// The m-point Gauss–Legendre rule, w_k = 2 / ((1 − y_k²) P'_m(y_k)²); exact for degree 2m − 1.
GaussRule gauss_rule(int m) {
  GaussRule rule;
  rule.y = interior_roots([m](Real y) { return legendre(m, y).first; }, m);
  for (const Real y : rule.y) {
    const Real dp = legendre_derivative(m, y);
    rule.w.push_back(2 / ((1 - y * y) * dp * dp));
  }
  return rule;
}

VectorL lagrange_integrals(const VectorL& nodes, Real x, const GaussRule& rule) {
  VectorL integral = VectorL::Zero(nodes.size());
  for (std::size_t k = 0; k < rule.y.size(); ++k) {
    const Real tau = x * (1 + rule.y[k]) / 2;
    integral += (x * rule.w[k] / 2) * lagrange_values(nodes, tau);
  }
  return integral;
}

}  // namespace

Real bracketed_root(const std::function<Real(Real)>& f, Real lo, Real hi) {
  const bool rising = f(lo) < 0;
  CATENA_ASSERT(rising == (f(hi) > 0), "bracketed_root: no sign change");
  for (;;) {
    const Real mid = lo + (hi - lo) / 2;
    if (mid <= lo || mid >= hi) break;  // adjacent long doubles
    const Real fm = f(mid);
    if (fm == 0) return mid;
    if ((fm < 0) == rising) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  return std::fabs(f(lo)) < std::fabs(f(hi)) ? lo : hi;
}

VectorL gauss_nodes(int s) {
  return to_unit_interval(interior_roots([s](Real y) { return legendre(s, y).first; }, s), true);
}

VectorL radau_right_nodes(int s) {
  // P_s − P_{s−1} vanishes at y = 1 (both are 1 there); the other s − 1 roots are interior.
  auto y = interior_roots(
      [s](Real t) {
        const auto [p, p_prev] = legendre(s, t);
        return p - p_prev;
      },
      s - 1);
  y.push_back(1);
  return to_unit_interval(std::move(y), false);
}

VectorL lobatto_nodes(int s) {
  std::vector<Real> y{-1};
  const auto inner = interior_roots([s](Real t) { return legendre_derivative(s - 1, t); }, s - 2);
  y.insert(y.end(), inner.begin(), inner.end());
  y.push_back(1);
  return to_unit_interval(std::move(y), true);
}

VectorL lagrange_values(const VectorL& nodes, Real x) {
  // Product form: well conditioned, unlike the monomial (Vandermonde) route.
  const Eigen::Index n = nodes.size();
  VectorL l = VectorL::Ones(n);
  for (Eigen::Index j = 0; j < n; ++j) {
    for (Eigen::Index m = 0; m < n; ++m) {
      if (m != j) l(j) *= (x - nodes(m)) / (nodes(j) - nodes(m));
    }
  }
  return l;
}

VectorL lagrange_integrals(const VectorL& nodes, Real x) {
  return lagrange_integrals(nodes, x, gauss_rule(static_cast<int>(nodes.size())));
}

MatrixL collocation_matrix(const VectorL& c) {
  const Eigen::Index s = c.size();
  const GaussRule rule = gauss_rule(static_cast<int>(s));
  MatrixL a(s, s);
  for (Eigen::Index i = 0; i < s; ++i) a.row(i) = lagrange_integrals(c, c(i), rule).transpose();
  return a;
}

VectorL quadrature_weights(const VectorL& c) { return lagrange_integrals(c, 1); }

MatrixL lobatto_iiic_matrix(const VectorL& c, const VectorL& b) {
  // With a_i1 = b_1 and c_1 = 0, C(s − 1) reads b_1 p(0) + Σ_{j≥2} a_ij p(c_j) = ∫_0^{c_i} p
  // for every p of degree ≤ s − 2; p = ℓ̃_k, the Lagrange basis on c_2..c_s, gives
  //   a_ik = ∫_0^{c_i} ℓ̃_k − b_1 ℓ̃_k(0),   k = 2..s.
  const Eigen::Index s = c.size();
  const VectorL tail = c.tail(s - 1);
  const VectorL tail_at_0 = lagrange_values(tail, 0);
  const GaussRule rule = gauss_rule(static_cast<int>(s - 1));
  MatrixL a(s, s);
  for (Eigen::Index i = 0; i < s; ++i) {
    a(i, 0) = b(0);
    a.row(i).tail(s - 1) = (lagrange_integrals(tail, c(i), rule) - b(0) * tail_at_0).transpose();
  }
  return a;
}

}  // namespace catena::solvers::detail
