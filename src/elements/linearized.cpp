#include "catena/elements/linearized.hpp"

#include <Eigen/Core>
#include <algorithm>

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
  const auto n = static_cast<Eigen::Index>(q0_.size());
  using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  using Vector = Eigen::VectorXd;
  if (r.force) {
    Eigen::Map<Vector> f(out.f, n);
    const Eigen::Map<const Vector> q(s.q.data(), n), q0(q0_.data(), n), f0(f0_.data(), n);
    f.noalias() = f0 + Eigen::Map<const Matrix>(K0_.data(), n, n) * (q - q0);
    if (!s.v.empty())
      f.noalias() +=
          Eigen::Map<const Matrix>(C0_.data(), n, n) * Eigen::Map<const Vector>(s.v.data(), n);
  }
  if (r.stiffness) std::copy(K0_.begin(), K0_.end(), out.K);
  if (r.damping) std::copy(C0_.begin(), C0_.end(), out.C);
}

}  // namespace catena::elements
