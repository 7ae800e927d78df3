#pragma once
// The static Jacobian ∂f/∂q of a (serial) SecondOrderSystem at a state, assembled and by
// central differences of its residual, both dense row-major over the global unknowns.
// Tests only.
#include <vector>

#include "catena/assembly/second_order_system.hpp"

namespace catena::test {

struct SystemJacobians {
  std::vector<double> analytic, finite_difference;  // n × n, row-major
  int n = 0;
};

// Not collective (PETSC_COMM_SELF): the reference state's value of every global unknown.
std::vector<double> reference_unknowns(const assembly::SecondOrderSystem& system);

// Not collective: `system` must live on PETSC_COMM_SELF. x: every global unknown.
SystemJacobians system_jacobians(assembly::SecondOrderSystem& system, const std::vector<double>& x,
                                 double t = 0.0);

}  // namespace catena::test
