#pragma once
// Cubic Hermite interpolation between two states of a step, the dense output of methods
// without a continuous extension of their own (HHT, step-doubled or PETSc TS steps).
#include <petscvec.h>

namespace catena::solvers {

// Collective. y(θ) for θ ∈ [0, 1] from y0, y1 and their derivatives d0, d1 (per unit time)
// on a step of length h: y = H1 y0 + h H2 d0 + H3 y1 + h H4 d1.
void hermite_interpolate(double theta, double h, Vec y0, Vec d0, Vec y1, Vec d1, Vec out);

}  // namespace catena::solvers
