#include "catena/elements/linearized.hpp"

#include "catena/core/error.hpp"

namespace catena::elements {

Linearized::Linearized(std::unique_ptr<Element> inner, std::span<const double> q0)
    : inner_(std::move(inner)), q0_(q0.begin(), q0.end()) {
  const auto n = static_cast<std::size_t>(inner_->n_dofs());
  CATENA_ASSERT(q0_.size() == n, "the state to linearise about has one value per DOF");
  f0_.assign(n, 0.0);
  K0_.assign(n * n, 0.0);
  C0_.assign(n * n, 0.0);
  const bool damps = inner_->has_damping();
  inner_->evaluate({q0_, {}, {}}, {true, true, damps},
                   {f0_.data(), K0_.data(), damps ? C0_.data() : nullptr});
}

void Linearized::evaluate(const LocalState& s, Request r, LocalOutput out) const {
  const std::size_t n = q0_.size();
  if (r.force)
    for (std::size_t i = 0; i < n; ++i) {
      double f = f0_[i];
      for (std::size_t j = 0; j < n; ++j) f += K0_[i * n + j] * (s.q[j] - q0_[j]);
      if (!s.v.empty())
        for (std::size_t j = 0; j < n; ++j) f += C0_[i * n + j] * s.v[j];
      out.f[i] = f;
    }
  if (r.stiffness) std::copy(K0_.begin(), K0_.end(), out.K);
  if (r.damping) std::copy(C0_.begin(), C0_.end(), out.C);
}

}  // namespace catena::elements
