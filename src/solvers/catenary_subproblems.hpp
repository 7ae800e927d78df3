#pragma once
// The initial estimate of catenary shape finding (docs/catenary.md "Shape finding"), two
// static problems on parts of the model:
//   1. the contact wire alone, held at its design heights at the dropper points (and at
//      the registrations whose height is held): the support reactions there are the
//      forces the droppers (and steady-arm preloads) must carry;
//   2. the messenger alone under those dropper forces: where the droppers' upper ends are.
// Each wire's prestrain is corrected until its mean axial force is its design tension.
#include <mpi.h>

#include <vector>

#include "catena/core/vec3.hpp"
#include "catena/model/model.hpp"

namespace catena::solvers::detail {

struct ContactWireLoads {
  std::vector<double> dropper_force;       // N, upward, per CatenaryLayout::droppers
  std::vector<double> registration_force;  // N, upward, per CatenaryLayout::registrations
  int n_solves = 0;
};

// Collective. Problem 1. `dropper_weight`: N per dropper, the half of its weight that
// hangs on the contact wire (a bar lumps half its mass at each end).
ContactWireLoads solve_contact_wire_held(MPI_Comm comm, const model::Model& model,
                                         const std::vector<double>& dropper_weight,
                                         double tension_rtol);

struct MessengerShape {
  std::vector<Vec3> dropper_top;  // m, the messenger node of each dropper
  double prestrain = 0.0;         // the messenger's, giving its design tension
  int n_solves = 0;
};

// Collective. Problem 2: the messenger with its supports and masses, each dropper pulling
// its node down with dropper_force + dropper_weight (N).
MessengerShape solve_messenger_loaded(MPI_Comm comm, const model::Model& model,
                                      const std::vector<double>& dropper_force,
                                      const std::vector<double>& dropper_weight,
                                      double tension_rtol);

// Not collective. The next prestrain of a wire whose mean axial force is N at prestrain
// ε, aiming at tension T: a Newton step on N(ε) = EA (ε + s(N)), where the sag strain
// s = N/EA − ε of a hanging wire scales as 1/N², so dN/dε = EA / (1 + 2 EA s / N).
double corrected_prestrain(double prestrain, double mean_force, double tension, double EA);

}  // namespace catena::solvers::detail
