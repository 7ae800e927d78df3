#include "rank_zero.hpp"

#include <exception>

#include "catena/core/error.hpp"
#include "catena/core/mpi_comm.hpp"

namespace catena::app {

void on_rank_zero(MPI_Comm comm, const std::string& file, const std::function<void()>& work) {
  std::exception_ptr failure;
  int failed = 0;
  if (mpi_rank(comm) == 0) {
    try {
      work();
    } catch (...) {
      failure = std::current_exception();
      failed = 1;
    }
  }
  MPI_Bcast(&failed, 1, MPI_INT, 0, comm);
  if (failure) std::rethrow_exception(failure);
  if (failed) throw InputError({file, 0, ""}, "the command failed on rank 0");
}

}  // namespace catena::app
