// SecondOrderSystem, part: replacing element kernels by their linearisation about a state
// (the linear structure of `analysis.structure: linear`; the class:
// include/catena/assembly/second_order_system.hpp).
#include "catena/assembly/second_order_system.hpp"
#include "catena/couplings/element_coupling.hpp"
#include "local_array.hpp"

namespace catena::assembly {

using detail::LocalArrayRead;

int SecondOrderSystem::linearize_elements(Vec q0, const std::function<bool(int)>& linearize) {
  scatter_to_local(q0, q_work_.get());
  const LocalArrayRead q(q_work_.get());
  int n = 0;
  for (size_t i = 0; i < couplings_.size(); ++i) {
    auto* element = dynamic_cast<couplings::ElementCoupling*>(couplings_[i].get());
    if (element == nullptr || element->origin() != couplings::ElementOrigin::element ||
        !linearize(element->source()))
      continue;
    const ActiveDofs dofs = active(i, 0.0, work_);
    const couplings::CouplingState s = gather(dofs, q.data(), nullptr, {}, 0.0, work_);
    element->linearize_about(s.q);
    ++n;
  }
  return n;
}

}  // namespace catena::assembly
