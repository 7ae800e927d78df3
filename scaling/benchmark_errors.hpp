#pragma once
// How the benchmarks end on an error: printed, not an abort's backtrace. Input errors are
// thrown on every rank alike (each rank reads the same generated scene text), so each
// returns 2 and PETSc finalises on all; any other error may be one rank's, so that rank
// ends the job rather than leave the others waiting in a collective call.
#include <mpi.h>
#include <petscsys.h>

#include <cstdio>
#include <exception>

#include "catena/core/error.hpp"
#include "catena/core/mpi_comm.hpp"

namespace catena::bench {

// Runs `body` (returning the exit code) inside the caller's PETSc session.
template <class Body>
int run_reporting_errors(const char* name, Body&& body) {
  try {
    return body();
  } catch (const InputError& e) {
    if (mpi_rank(PETSC_COMM_WORLD) == 0) std::fprintf(stderr, "%s: %s\n", name, e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", name, e.what());
    MPI_Abort(MPI_COMM_WORLD, 1);
    return 1;
  }
}

}  // namespace catena::bench
