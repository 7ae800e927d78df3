// SecondOrderSystem, part: the structure's matrices without its moving contacts and loads
// (the modal model's linear part; the class: include/catena/assembly/second_order_system.hpp).
#include "catena/assembly/petsc_call.hpp"
#include "catena/assembly/second_order_system.hpp"
#include "catena/core/error.hpp"
#include "catena/couplings/bilateral_contact.hpp"
#include "catena/couplings/moving_load.hpp"
#include "catena/couplings/pantograph_contact.hpp"

namespace catena::assembly {

SecondOrderSystem::StructureMatrices SecondOrderSystem::structure_matrices(Vec q0) {
  CATENA_ASSERT(!linear_, "structure_matrices: before linearize_elements");
  std::vector<size_t> structure;
  for (size_t i = 0; i < couplings_.size(); ++i) {
    const couplings::Coupling* c = couplings_[i].get();
    if (dynamic_cast<const couplings::PantographContact*>(c) == nullptr &&
        dynamic_cast<const couplings::BilateralContact*>(c) == nullptr &&
        dynamic_cast<const couplings::MovingLoad*>(c) == nullptr)
      structure.push_back(i);
  }
  StructureMatrices s;
  s.K = create_matrix();
  s.C = create_matrix();
  s.M = create_matrix();
  const JacobianCoefficients stiffness_damping[2] = {{1.0, 0.0, 0.0, 0.0, 0.0},
                                                     {0.0, 1.0, 0.0, 0.0, 0.0}};
  const JacobianCoefficients mass{0.0, 0.0, 1.0, 0.0, 0.0};
  const Mat K_C[2] = {s.K.get(), s.C.get()};
  const EvalPoint at{q0, nullptr, {}, 0.0};
  assemble_matrices(at, stiffness_damping, K_C, structure);
  const Mat M = s.M.get();
  assemble_matrices(at, {&mass, 1}, {&M, 1}, structure);
  s.f0 = create_vector();
  sum_forces(at, structure, s.f0.get(), nullptr);
  return s;
}

}  // namespace catena::assembly
