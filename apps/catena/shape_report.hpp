#pragma once
// `catena run` on a scene with a `catenary`: shape finding before the analysis, and what
// it found on the console (the dropper lengths, the remaining height error, the tensions).
#include <mpi.h>

#include <cstdio>

#include "catena/model/model.hpp"

namespace catena::app {

// Collective. When m has a catenary, runs solvers::find_catenary_shape (which sets the
// dropper lengths, steady-arm preloads and wire prestrains in m) and prints its report on
// rank 0 to `out` (stderr where stdout carries JSON); does nothing otherwise.
void shape_catenary(MPI_Comm comm, model::Model& m, std::FILE* out = stdout);

}  // namespace catena::app
