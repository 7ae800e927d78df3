#pragma once
// The static solve every command that needs an equilibrium runs the same way: the static
// solver with progress lines, started from each line's elastic catenary where that
// applies (solvers/statics/hanging_cable_guess.hpp), as the "Statics" log stage.
#include <petscvec.h>

#include "catena/assembly/second_order_system.hpp"
#include "catena/solvers/statics/static_solver.hpp"
#include "cli.hpp"

namespace catena::app {

// Collective. The equilibrium into q (the reference state on entry).
solvers::StaticReport solve_statics(assembly::SecondOrderSystem& system, Vec q,
                                    const CommandLine& cl);

}  // namespace catena::app
