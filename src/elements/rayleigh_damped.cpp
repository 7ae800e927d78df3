#include "catena/elements/rayleigh_damped.hpp"

#include "catena/core/error.hpp"

namespace catena::elements {

RayleighDamped::RayleighDamped(std::unique_ptr<Element> inner, RayleighCoefficients c,
                               std::span<const double> q_ref)
    : inner_(std::move(inner)) {
  const int n = inner_->n_dofs();
  CATENA_ASSERT(static_cast<int>(q_ref.size()) == n, "RayleighDamped: q_ref size");
  const size_t nn = static_cast<size_t>(n) * static_cast<size_t>(n);
  std::vector<double> M(nn), K(nn), f(static_cast<size_t>(n));
  inner_->mass(M.data());
  inner_->evaluate(LocalState{q_ref, {}, LoadPath{}}, Request{true, true, false},
                   LocalOutput{f.data(), K.data(), nullptr});
  D_.resize(nn);
  for (size_t k = 0; k < nn; ++k) D_[k] = c.mass * M[k] + c.stiffness * K[k];
}

void RayleighDamped::evaluate(const LocalState& s, Request r, LocalOutput out) const {
  inner_->evaluate(s, r, out);
  const int n = inner_->n_dofs();
  if (r.force && !s.v.empty())
    for (int i = 0; i < n; ++i) {
      double sum = 0.0;
      for (int j = 0; j < n; ++j) sum += D_[static_cast<size_t>(i * n + j)] * s.v[j];
      out.f[i] += sum;
    }
  if (r.damping)
    for (size_t k = 0; k < D_.size(); ++k) out.C[k] += D_[k];
}

}  // namespace catena::elements
