#include "rank_zero.hpp"

#include <exception>

#include "catena/core/error.hpp"
#include "catena/core/mpi_comm.hpp"
#include "catena/io/output_error.hpp"

namespace catena::app {
namespace {

// What rank 0's failure was, so that every rank leaves with main()'s exit code for it.
enum Failure : int { none = 0, input, output, numerical, other };

Failure kind_of(const std::exception_ptr& failure) {
  try {
    std::rethrow_exception(failure);
  } catch (const InputError&) {
    return input;
  } catch (const OutputError&) {
    return output;
  } catch (const NumericalError&) {
    return numerical;
  } catch (...) {
    return other;
  }
}

}  // namespace

void on_rank_zero(MPI_Comm comm, const std::string& file, const std::function<void()>& work) {
  std::exception_ptr failure;
  int kind = none;
  if (mpi_rank(comm) == 0) {
    try {
      work();
    } catch (...) {
      failure = std::current_exception();
      kind = kind_of(failure);
    }
  }
  MPI_Bcast(&kind, 1, MPI_INT, 0, comm);
  if (failure) std::rethrow_exception(failure);
  const std::string message = "'" + file + "': the command failed on rank 0";
  switch (kind) {
    case none:
      return;
    case input:
      throw InputError({file, 0, ""}, "the command failed on rank 0");
    case output:
      throw OutputError(message);
    case numerical:
      throw NumericalError(message);
    default:
      throw Error(message);
  }
}

}  // namespace catena::app
