// SecondOrderSystem, part: replacing element kernels by their linearisation about a state
// (the linear structure of `analysis.structure: linear`; the class:
// include/catena/assembly/second_order_system.hpp).
#include "catena/assembly/petsc_call.hpp"
#include "catena/assembly/second_order_system.hpp"
#include "catena/core/error.hpp"
#include "catena/couplings/element_coupling.hpp"
#include "local_array.hpp"

namespace catena::assembly {

using detail::LocalArrayRead;

int SecondOrderSystem::linearize_elements(Vec q0, const std::function<bool(int)>& linearize) {
  CATENA_ASSERT(!linear_, "linearize_elements: the system has its linear block already");
  std::vector<size_t> block, rest;
  {
    scatter_to_local(q0, q_work_.get());
    const LocalArrayRead q(q_work_.get());
    for (size_t i = 0; i < couplings_.size(); ++i) {
      auto* element = dynamic_cast<couplings::ElementCoupling*>(couplings_[i].get());
      if (element == nullptr || element->origin() != couplings::ElementOrigin::element ||
          !linearize(element->source())) {
        rest.push_back(i);
        continue;
      }
      const ActiveDofs dofs = active(i, 0.0, q.data(), work_);
      const couplings::CouplingState s = gather(dofs, q.data(), nullptr, {}, 0.0, work_);
      element->linearize_about(s.q);
      block.push_back(i);
    }
  }
  // Collective from here on every rank, whether or not it linearised anything.
  auto b = std::make_unique<LinearBlock>();
  b->K = create_matrix();
  b->C = create_matrix();
  b->M = create_matrix();
  // Two matrices per pass at most (assemble_matrices' buffers).
  const JacobianCoefficients stiffness_damping[2] = {{1.0, 0.0, 0.0, 0.0, 0.0},
                                                     {0.0, 1.0, 0.0, 0.0, 0.0}};
  const JacobianCoefficients mass{0.0, 0.0, 1.0, 0.0, 0.0};
  const Mat K_C[2] = {b->K.get(), b->C.get()};
  const EvalPoint at{q0, nullptr, {}, 0.0};
  assemble_matrices(at, stiffness_damping, K_C, block);
  const Mat M = b->M.get();
  assemble_matrices(at, {&mass, 1}, {&M, 1}, block);
  b->f0 = create_vector();
  sum_forces(at, block, b->f0.get(), &b->squares);
  b->q0 = create_vector();
  CATENA_PETSC(VecCopy(q0, b->q0.get()));
  b->dq = create_vector();
  linear_ = std::move(b);
  evaluated_ = std::move(rest);
  return static_cast<int>(block.size());
}

}  // namespace catena::assembly
