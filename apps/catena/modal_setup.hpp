#pragma once
// analysis.structure: modal — the modal model about the static equilibrium, its modes from
// the scene's modal basis file when that holds this structure's modes (checked against the
// structure: catena/solvers/modes/modes_check.hpp), else computed by spectrum slicing and
// written to the file when the scene names one (analysis.modal_basis).
#include <petscvec.h>

#include <memory>

#include "catena/assembly/second_order_system.hpp"
#include "catena/solvers/time/time_integrator.hpp"

namespace catena::app {

// Collective. q0: the static equilibrium. Prints where the modes come from, what the build
// cost and the model's size.
std::unique_ptr<solvers::TimeIntegrator> make_modal_integrator(assembly::SecondOrderSystem& system,
                                                               Vec q0, int rank);

}  // namespace catena::app
