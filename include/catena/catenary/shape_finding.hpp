#pragma once
// Shape finding of a catenary built from design data (model::CatenaryLayout): the dropper
// unstretched lengths that put the contact wire at its design heights (the pre-sag
// parabola) in static equilibrium, together with the steady-arm preloads that hold the
// registration points at their design height and the wire prestrains that give each
// wire (stitch wires included) its design tension in that equilibrium. Method and
// references: docs/catenary.md.
//
//   1. estimate: the contact wire alone, held at its design heights at the droppers
//      → dropper forces F_i (support reactions) and registration forces; the messenger
//      (with its stitch wires) alone under the F_i → the droppers' upper ends;
//      l0_i = gap_i / (1 + F_i/EA_i) (or gap_i − F_i/k_i);
//   2. correct: solve the whole structure's statics and update each length by its height
//      error e_i = z_i − z_design,i (l0_i += e_i, the fixed point the decoupled estimate
//      suggests), each held registration's preload by P_j −= (k_arm + k_c,j/4) e_j
//      (k_c,j = T_c (1/a_left + 1/a_right), the contact wire's local stiffness) and the
//      prestrain of a wire whose mean axial force is off its tension by a Newton step;
//      repeat until max |e| < height_tolerance and every wire's tension is within
//      tension_rtol.
// Every static solve is StaticSolver from the reference configuration, so the results do
// not depend on the previous iterate's state, only on the lengths, loads and prestrains.
#include <mpi.h>

#include <functional>
#include <vector>

#include "catena/model/model.hpp"

namespace catena::catenary {

struct ShapeFindingOptions {
  double height_tolerance = 1e-4;  // m: max |z − z_design| at droppers and held registrations
  double tension_rtol = 1e-4;      // mean axial force of each wire within this of its tension
  int max_iterations = 30;         // whole-structure static solves
  // Called on every rank after each whole-structure static solve with its number and the
  // largest height error then (m): a long line's shape finding takes minutes.
  std::function<void(int iteration, double max_height_error)> on_iteration;
};

struct ShapeFindingReport {
  // Per model::CatenaryLayout::droppers, at the final equilibrium:
  std::vector<double> dropper_lengths;  // m, unstretched (BarProps::unstretched_length)
  std::vector<double> dropper_forces;   // N, axial
  std::vector<double> height_errors;    // m, z − z_design of the contact wire at the dropper
  // Per model::CatenaryLayout::registrations:
  std::vector<double> registration_preloads;  // N, upward (0 where the height is not held)
  std::vector<double> registration_errors;    // m, z − z_design (0 where not held)
  double max_height_error = 0.0;              // m, max |error| over droppers and held registrations
  double contact_wire_tension = 0.0;          // N, mean axial force at the equilibrium
  double messenger_tension = 0.0;             // N
  std::vector<double> stitch_tensions;        // N, per model::CatenaryLayout::stitch_wires
  std::vector<double> error_history;          // m, max |error| after each whole-structure solve
  int n_iterations = 0;                       // whole-structure static solves
  int n_static_solves = 0;                    // all static solves, the estimate's included
};

// Collective: every rank passes the same model and gets the same report. Requires
// model.catenary. Sets the dropper lengths (and EA = stiffness × length where the design
// gives a stiffness), the steady-arm preloads (Model::nodal_loads) and the wires'
// prestrains in `model`. The shape is the catenary's alone: pantograph contacts and moving
// loads are left out of every solve (the design heights are those of the unloaded line).
// Throws NumericalError when a dropper would need a non-positive
// length (the messenger hangs below the contact wire: raise system_height or the
// messenger's tension), when the iteration does not reach height_tolerance within
// max_iterations, and whatever StaticSolver throws.
ShapeFindingReport find_catenary_shape(MPI_Comm comm, model::Model& model,
                                       const ShapeFindingOptions& options = {});

}  // namespace catena::catenary
