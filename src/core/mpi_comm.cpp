#include "catena/core/mpi_comm.hpp"

#include <limits>

#include "catena/core/error.hpp"

namespace catena {

int mpi_rank(MPI_Comm comm) {
  int r = 0;
  MPI_Comm_rank(comm, &r);
  return r;
}

int mpi_size(MPI_Comm comm) {
  int s = 1;
  MPI_Comm_size(comm, &s);
  return s;
}

void broadcast_string(MPI_Comm comm, std::string& s, int root) {
  unsigned long long n = s.size();
  MPI_Bcast(&n, 1, MPI_UNSIGNED_LONG_LONG, root, comm);
  if (n > static_cast<unsigned long long>(std::numeric_limits<int>::max()))
    throw Error("broadcast_string: string of " + std::to_string(n) + " bytes is too large");
  s.resize(n);
  if (n > 0) MPI_Bcast(s.data(), static_cast<int>(n), MPI_CHAR, root, comm);
}

bool any_rank(MPI_Comm comm, bool flag) {
  int local = flag ? 1 : 0, global = 0;
  MPI_Allreduce(&local, &global, 1, MPI_INT, MPI_MAX, comm);
  return global != 0;
}

}  // namespace catena
