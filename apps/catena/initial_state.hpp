#pragma once
// The initial state of a dynamic analysis from the scene's `analysis.initial` settings.
#include <petscvec.h>

#include "catena/assembly/second_order_system.hpp"

namespace catena::app {

// Collective. q: the start configuration (static equilibrium or reference) on entry; adds
// the scene's nodal offsets to the free DOFs (fixed ones keep their support values) and
// sets v to the uniform initial velocity on free position DOFs (zero elsewhere), plus each
// rigid body's velocity and angular velocity on its node (ė_k = ω × e_k).
void apply_initial_conditions(const assembly::SecondOrderSystem& system, Vec q, Vec v);

}  // namespace catena::app
