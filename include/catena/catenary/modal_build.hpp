#pragma once
// Building the modal model (solvers/modal/modal_model.hpp) of a scene about its static
// equilibrium: the structure's matrices without contacts (SecondOrderSystem::
// structure_matrices), the catenary's modes below the cut-off over every free DOF but the
// pantographs' (solvers/modes: spectrum slicing), modal damping and loads, the pantographs'
// dense matrices, and the sites: the contact wire's mode shapes along each pantograph's
// path and each tension-only dropper's elongation per mode.
//
// Refused, with the reason: constraints (multipliers), moving loads, tension-only cables
// (cable droppers: use the bar droppers).
#include "catena/assembly/second_order_system.hpp"
#include "catena/solvers/modal/modal_model.hpp"

namespace catena::catenary {

struct ModalBuildReport {
  double seconds = 0.0;        // wall time of the whole build, the eigen-solve included
  double eigen_seconds = 0.0;  // the eigen-solve alone
  int krylov_restarts = 0;
  double correction_seconds = 0.0;  // the static correction (a solve per site)
  int correction_solves = 0;
  double worst_residual = 0.0;  // largest relative eigen-residual
};

// Collective. q0: the static equilibrium. cutoff: Hz (> 0).
solvers::ModalModel build_modal_model(assembly::SecondOrderSystem& system, Vec q0, double cutoff,
                                      ModalBuildReport* report = nullptr);

}  // namespace catena::catenary
