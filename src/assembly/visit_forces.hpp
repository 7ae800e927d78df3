#pragma once
// SecondOrderSystem::visit_forces, the residual's loop over the couplings (assembly-internal:
// a template, so the per-coupling visitor is inlined).
#include <memory>
#include <span>

#include "catena/assembly/second_order_system.hpp"
#include "local_array.hpp"

namespace catena::assembly {

template <class Fn>
void SecondOrderSystem::visit_forces(const EvalPoint& p, Fn&& fn,
                                     const std::vector<size_t>* only) const {
  scatter_to_local(p.q, q_work_.get());
  if (p.v) scatter_to_local(p.v, v_work_.get());
  const detail::LocalArrayRead q(q_work_.get());
  std::unique_ptr<detail::LocalArrayRead> v;
  if (p.v) v = std::make_unique<detail::LocalArrayRead>(v_work_.get());
  const size_t n = only ? only->size() : couplings_.size();
  for (size_t k = 0; k < n; ++k) {
    const size_t i = only ? (*only)[k] : k;
    const ActiveDofs dofs = active(i, p.t, q.data(), work_);
    if (dofs.n == 0) continue;
    if (work_.f.size() < dofs.n) work_.f.resize(dofs.n);
    evaluate(i, dofs, q.data(), v ? v->data() : nullptr, p.path, p.t, work_.f.data(), {}, work_);
    fn(i, dofs, std::span<const double>(work_.f.data(), dofs.n));
  }
}

}  // namespace catena::assembly
