#pragma once
// Forward-mode automatic differentiation with fixed-size derivative arrays (no
// allocation), used by element kernels to get exact gradients and Hessians of strain
// measures with respect to a handful of local arguments. Not finite differences: the
// results are exact to round-off, so they are fit for production Jacobians.
//
//   Dual1<N>: value and gradient (N partials).
//   Dual2<N>: value, gradient and Hessian (packed upper triangle, N(N+1)/2 entries):
//             second-order truncated Taylor arithmetic. For a product
//               (ab)'' = a b'' + b a'' + a' b'ᵀ + b' a'ᵀ,
//             for a function f(a): f(a)'' = f'(a) a'' + f''(a) a' a'ᵀ.
// Only the operations the kernels need are provided: + − × ÷ with duals and doubles,
// unary −, sqrt, atan2. Seed the independent variables with variable(value, index).
#include <array>
#include <cmath>

namespace catena::elements {

template <int N>
struct Dual1 {
  double v = 0.0;
  std::array<double, N> g{};

  constexpr Dual1() = default;
  constexpr Dual1(double value) : v(value) {}  // NOLINT: constants promote implicitly
  static constexpr Dual1 variable(double value, int index) {
    Dual1 d(value);
    d.g[index] = 1.0;
    return d;
  }
  double value() const { return v; }
  double grad(int i) const { return g[i]; }

  // a ← α a + β b (gradient part), the building block of all binary operations.
  static Dual1 combine(double value, double alpha, const Dual1& a, double beta, const Dual1& b) {
    Dual1 r(value);
    for (int i = 0; i < N; ++i) r.g[i] = alpha * a.g[i] + beta * b.g[i];
    return r;
  }
  // f(a) given f(a.v), f'(a.v) (f'' unused at first order).
  static Dual1 chain(const Dual1& a, double f, double df, double /*ddf*/) {
    Dual1 r(f);
    for (int i = 0; i < N; ++i) r.g[i] = df * a.g[i];
    return r;
  }
  // f(a, b) given its value, gradient (fa, fb) and Hessian (unused at first order).
  static Dual1 chain2(const Dual1& a, const Dual1& b, double f, double fa, double fb,
                      double /*faa*/, double /*fab*/, double /*fbb*/) {
    return combine(f, fa, a, fb, b);
  }
};

template <int N>
struct Dual2 {
  static constexpr int kPacked = N * (N + 1) / 2;
  double v = 0.0;
  std::array<double, N> g{};
  std::array<double, kPacked> h{};  // upper triangle, row by row: (0,0) (0,1) .. (1,1) ..

  constexpr Dual2() = default;
  constexpr Dual2(double value) : v(value) {}  // NOLINT: constants promote implicitly
  static constexpr Dual2 variable(double value, int index) {
    Dual2 d(value);
    d.g[index] = 1.0;
    return d;
  }
  double value() const { return v; }
  double grad(int i) const { return g[i]; }
  double hess(int i, int j) const {
    if (i > j) {
      const int t = i;
      i = j;
      j = t;
    }
    return h[i * N - i * (i - 1) / 2 + (j - i)];
  }

  static Dual2 combine(double value, double alpha, const Dual2& a, double beta, const Dual2& b) {
    Dual2 r(value);
    for (int i = 0; i < N; ++i) r.g[i] = alpha * a.g[i] + beta * b.g[i];
    for (int k = 0; k < kPacked; ++k) r.h[k] = alpha * a.h[k] + beta * b.h[k];
    return r;
  }
  // Product a·b scaled: adds the cross term a' b'ᵀ + b' a'ᵀ to α a'' + β b''.
  static Dual2 product(const Dual2& a, const Dual2& b) {
    Dual2 r = combine(a.v * b.v, b.v, a, a.v, b);
    int k = 0;
    for (int i = 0; i < N; ++i)
      for (int j = i; j < N; ++j, ++k) r.h[k] += a.g[i] * b.g[j] + b.g[i] * a.g[j];
    return r;
  }
  static Dual2 chain(const Dual2& a, double f, double df, double ddf) {
    Dual2 r(f);
    for (int i = 0; i < N; ++i) r.g[i] = df * a.g[i];
    int k = 0;
    for (int i = 0; i < N; ++i)
      for (int j = i; j < N; ++j, ++k) r.h[k] = df * a.h[k] + ddf * a.g[i] * a.g[j];
    return r;
  }
  // f(a, b): f'' = fa a'' + fb b'' + faa a'a'ᵀ + fbb b'b'ᵀ + fab (a'b'ᵀ + b'a'ᵀ).
  static Dual2 chain2(const Dual2& a, const Dual2& b, double f, double fa, double fb, double faa,
                      double fab, double fbb) {
    Dual2 r = combine(f, fa, a, fb, b);
    int k = 0;
    for (int i = 0; i < N; ++i)
      for (int j = i; j < N; ++j, ++k)
        r.h[k] += faa * a.g[i] * a.g[j] + fbb * b.g[i] * b.g[j] +
                  fab * (a.g[i] * b.g[j] + b.g[i] * a.g[j]);
    return r;
  }
};

// ---- Arithmetic shared by Dual1 and Dual2 -------------------------------------------
template <class D>
concept DualNumber = requires(const D& d) {
  D::chain(d, 0.0, 0.0, 0.0);
};

template <DualNumber D>
D operator+(const D& a, const D& b) {
  return D::combine(a.v + b.v, 1.0, a, 1.0, b);
}
template <DualNumber D>
D operator-(const D& a, const D& b) {
  return D::combine(a.v - b.v, 1.0, a, -1.0, b);
}
template <DualNumber D>
D operator-(const D& a) {
  return D::chain(a, -a.v, -1.0, 0.0);
}
template <DualNumber D>
D operator+(const D& a, double b) {
  return D::chain(a, a.v + b, 1.0, 0.0);
}
template <DualNumber D>
D operator+(double a, const D& b) {
  return b + a;
}
template <DualNumber D>
D operator-(const D& a, double b) {
  return D::chain(a, a.v - b, 1.0, 0.0);
}
template <DualNumber D>
D operator-(double a, const D& b) {
  return D::chain(b, a - b.v, -1.0, 0.0);
}
template <DualNumber D>
D operator*(const D& a, double b) {
  return D::chain(a, a.v * b, b, 0.0);
}
template <DualNumber D>
D operator*(double a, const D& b) {
  return b * a;
}
template <DualNumber D>
D operator/(const D& a, double b) {
  return a * (1.0 / b);
}

template <int N>
Dual1<N> operator*(const Dual1<N>& a, const Dual1<N>& b) {
  return Dual1<N>::combine(a.v * b.v, b.v, a, a.v, b);
}
template <int N>
Dual2<N> operator*(const Dual2<N>& a, const Dual2<N>& b) {
  return Dual2<N>::product(a, b);
}

// 1/a: f = 1/x, f' = −1/x², f'' = 2/x³.
template <DualNumber D>
D reciprocal(const D& a) {
  const double r = 1.0 / a.v;
  return D::chain(a, r, -r * r, 2.0 * r * r * r);
}
template <DualNumber D>
D operator/(const D& a, const D& b) {
  return a * reciprocal(b);
}
template <DualNumber D>
D operator/(double a, const D& b) {
  return reciprocal(b) * a;
}

// atan2(y, x), r² = x² + y²: ∂/∂y = x/r², ∂/∂x = −y/r², ∂²/∂y² = −2xy/r⁴,
// ∂²/∂x² = 2xy/r⁴, ∂²/∂x∂y = (y² − x²)/r⁴.
template <DualNumber D>
D atan2(const D& y, const D& x) {
  const double r2 = x.v * x.v + y.v * y.v, r4 = r2 * r2;
  return D::chain2(y, x, std::atan2(y.v, x.v), x.v / r2, -y.v / r2, -2.0 * x.v * y.v / r4,
                   (y.v * y.v - x.v * x.v) / r4, 2.0 * x.v * y.v / r4);
}

// sqrt: f' = 1/(2√x), f'' = −1/(4 x √x).
template <DualNumber D>
D sqrt(const D& a) {
  const double s = std::sqrt(a.v);
  return D::chain(a, s, 0.5 / s, -0.25 / (s * a.v));
}

}  // namespace catena::elements
