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
#include "catena/solvers/modes/modal_analysis.hpp"

namespace catena::catenary {

struct ModalBuildReport {
  double seconds = 0.0;             // wall time of the build from the modes on
  double correction_seconds = 0.0;  // the static correction (a solve per site)
  int correction_solves = 0;
};

// The structure about q0 and how its DOFs divide: the pantographs' (kept as they are) and
// the catenary's (in modes).
struct ModalStructure {
  assembly::SecondOrderSystem::StructureMatrices matrices;
  std::vector<PetscInt> pantograph_dofs;  // global, ascending, the same list on every rank
  std::vector<PetscInt> catenary_dofs;    // this rank's owned, ascending
};

// Collective. q0: the static equilibrium. Throws InputError for what the model refuses.
ModalStructure modal_structure(assembly::SecondOrderSystem& system, Vec q0);

// Collective. The model from the structure and the catenary's modes below cutoff (Hz):
// solvers::compute_modes_below over structure.catenary_dofs, or a stored basis that
// solvers::modes_mismatch accepted.
solvers::ModalModel build_modal_model(assembly::SecondOrderSystem& system, Vec q0,
                                      ModalStructure structure, solvers::Modes modes, double cutoff,
                                      ModalBuildReport* report = nullptr);

}  // namespace catena::catenary
