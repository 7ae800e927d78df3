#pragma once
// Thin helpers over MPI used by every layer that communicates.
#include <mpi.h>

#include <string>

namespace catena {

// Not collective.
int mpi_rank(MPI_Comm comm);
int mpi_size(MPI_Comm comm);

// Collective: rank `root`'s string is copied to every rank.
void broadcast_string(MPI_Comm comm, std::string& s, int root = 0);

// Collective: true on every rank iff `flag` is true on any rank.
bool any_rank(MPI_Comm comm, bool flag);

}  // namespace catena
