#pragma once
// The static solve every command that needs an equilibrium runs the same way: the static
// solver with progress lines, started from each line's elastic catenary where that
// applies (solvers/statics/hanging_cable_guess.hpp), as the "Statics" log stage.
#include <petscvec.h>

#include <utility>
#include <vector>

#include "catena/assembly/second_order_system.hpp"
#include "catena/core/vec3.hpp"
#include "catena/solvers/statics/static_solver.hpp"
#include "cli.hpp"

namespace catena::app {

// Collective. The equilibrium into q (the reference state on entry).
solvers::StaticReport solve_statics(assembly::SecondOrderSystem& system, Vec q,
                                    const CommandLine& cl);

// Collective. The same for a model with what a dynamic run's static start holds:
//  - each slider at its start: a slider's travel along a straight path has no stiffness, so
//    the equilibrium with it free is singular at the first Newton step (and, on a sagging
//    wire, is the trolley run to the lowest point);
//  - each absorbing end where it is (model::AbsorbingEnd: in the run the line beyond holds
//    it, which statics does not model).
// The equilibrium is solved on a copy of the model where these are supported, and copied
// into q, laid out as `system`'s (where they are free): a dynamic run then releases them at
// t = 0.
// A catenary window's static start (window_statics.hpp) also holds its absorbing ends
// elsewhere than at their reference positions, and solves the catenary alone:
struct StaticHolds {
  struct End {
    int node = 0;
    Vec3 position, slope;  // m, 1: where it is held (in q too), position and slope r_x
  };
  std::vector<End> ends_at;  // absorbing ends held there
  // Without the pantographs' contacts (what the pantographs do alone is of no use then).
  bool catenary_alone = false;
};
solvers::StaticReport solve_statics_holding(assembly::SecondOrderSystem& system, Vec q,
                                            const CommandLine& cl, const StaticHolds& holds = {});

}  // namespace catena::app
