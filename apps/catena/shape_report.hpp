#pragma once
// `catena run` on a scene with a `catenary`: shape finding before the analysis, and what
// it found on the console (the dropper lengths, the remaining height error, the tensions).
#include <mpi.h>

#include <cstdio>

#include "catena/model/model.hpp"

namespace catena::app {

// Collective. When m has a catenary, runs catenary::find_catenary_shape (which sets the
// dropper lengths, steady-arm preloads and wire prestrains in m) and prints its report on
// rank 0 to `out` (stderr where stdout carries JSON); does nothing otherwise.
// Prints a progress line (rank 0, to `out`) after a whole-structure solve once
// `progress_seconds` have passed since the last (0: none).
void shape_catenary(MPI_Comm comm, model::Model& m, std::FILE* out, double progress_seconds);

// The highest first axial frequency of the cable droppers (rad/s; 0 without cable droppers
// with mass): a cable dropper's mass on its own EA, ω1 = (π/l0) √(EA/μ), the first mode of
// a rod of unstretched length l0 held at both ends (the wires barely move at that
// frequency); a bar dropper has no such mode. After shape finding (l0 set).
double cable_dropper_axial_omega(const model::Model& m);

// Not collective. Prints a warning to `out` when a fixed step leaves that mode unresolved.
void warn_unresolved_dropper_mode(const model::Model& m, std::FILE* out = stderr);

}  // namespace catena::app
