#pragma once
// The static start of a catenary window (model::CatenaryWindow). The window stands for a
// line that repeats, but its ends, held where the builder put them, hang otherwise than the
// line does there: an interior support of EN 50318's messenger sags 28 mm on its spring, the
// held end does not, and a pinned end leaves the wires' slope free where the line holds it.
// The spans next to the ends hang otherwise with them (the end spans' wires up to 3.5 mm
// lower on a mesh of 1 m elements, and a registration point's static height up to 1.8 mm
// off), and the window moves that into its inside. So each end is held where the line has
// it, position and slope, found by a fixed point on the catenary alone (no pantographs):
// each end takes its image's position (moved by the period) and slope, one period inside the
// window, until they agree within 10 µm (shape finding's tolerance is 0.1 mm). The run then starts
// from the equilibrium with the pantographs and the ends held there (the absorbing ends keep the
// force and the slope's generalised force that held them: elements/absorbing_end.hpp), and the
// spans that enter the window ahead start from the catenary's own.
#include <petscvec.h>

#include <memory>

#include "catena/assembly/second_order_system.hpp"
#include "cli.hpp"
#include "window_mover.hpp"

namespace catena::app {

// Collective. Into q (the reference state on entry), the run's static start; into q_line
// (any values on entry) the catenary's own static state with the ends in the same place.
void solve_window_statics(assembly::SecondOrderSystem& system, Vec q, Vec q_line,
                          const CommandLine& cl);

// Collective. A catenary window's static start into q (the reference state on entry), and
// its mover, which the catenary's own static state is given to for the spans that enter.
std::unique_ptr<WindowMover> start_window(assembly::SecondOrderSystem& system, Vec q,
                                          const CommandLine& cl);

}  // namespace catena::app
