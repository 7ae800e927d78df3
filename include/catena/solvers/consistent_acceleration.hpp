#pragma once
// The acceleration consistent with a state: M a = −f(t, q, v). Needed to start HHT (whose
// recurrence carries a) and to predict the first IRK stages.
#include <petscmat.h>

#include "catena/assembly/second_order_system.hpp"

namespace catena::solvers {

// Collective. Solves M a = −f(t, q, v) with a Cholesky factorisation of the (constant)
// mass matrix M (options prefix -mass_). Throws NumericalError if M is singular (a free
// DOF without mass), naming the likely cause.
void consistent_acceleration(assembly::SecondOrderSystem& system, Mat mass, double t, Vec q,
                             Vec v, Vec a);

}  // namespace catena::solvers
