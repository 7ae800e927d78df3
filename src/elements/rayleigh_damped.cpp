#include "catena/elements/rayleigh_damped.hpp"

#include "catena/core/error.hpp"

#include <Eigen/Core>

namespace catena::elements {
namespace {

// y += D x, D row-major n × n; N the size when the compiler may know it (else Dynamic).
template <int N>
void add_product(const double* D, const double* x, double* y, int n) {
  using Matrix = Eigen::Matrix<double, N, N, Eigen::RowMajor>;
  using Vector = Eigen::Matrix<double, N, 1>;
  Eigen::Map<Vector>(y, n).noalias() +=
      Eigen::Map<const Matrix>(D, n, n) * Eigen::Map<const Vector>(x, n);
}

}  // namespace

RayleighDamped::RayleighDamped(std::unique_ptr<Element> inner, RayleighCoefficients c,
                               std::span<const double> q_ref, std::shared_ptr<MatrixArena> arena)
    : inner_(std::move(inner)) {
  const int n = inner_->n_dofs();
  CATENA_ASSERT(static_cast<int>(q_ref.size()) == n, "RayleighDamped: q_ref size");
  const size_t nn = static_cast<size_t>(n) * static_cast<size_t>(n);
  // Without a list's arena, one of the element's own, the matrix's size.
  arena_ = arena ? std::move(arena) : std::make_shared<MatrixArena>(nn);
  std::vector<double> M(nn), K(nn), f(static_cast<size_t>(n));
  inner_->mass(M.data());
  inner_->evaluate(LocalState{q_ref, {}, LoadPath{}}, Request{true, true, false},
                   LocalOutput{f.data(), K.data(), nullptr});
  D_ = arena_->allocate(nn);
  for (size_t k = 0; k < nn; ++k) D_[k] = c.mass * M[k] + c.stiffness * K[k];
}

void RayleighDamped::evaluate(const LocalState& s, Request r, LocalOutput out) const {
  inner_->evaluate(s, r, out);
  const int n = inner_->n_dofs();
  // One Eigen matrix–vector product (vectorised; the plain row-times-vector loop chained
  // n dependent additions per row). The cable's 12 × 12 at a size known to the compiler:
  // Eigen's run-time-sized kernel spent a third of its time on set-up at this size.
  if (r.force && !s.v.empty()) {
    if (n == 12)
      add_product<12>(D_, s.v.data(), out.f, n);
    else
      add_product<Eigen::Dynamic>(D_, s.v.data(), out.f, n);
  }
  if (r.damping)
    for (int k = 0; k < n * n; ++k) out.C[k] += D_[k];
}

}  // namespace catena::elements
