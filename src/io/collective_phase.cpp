#include "collective_phase.hpp"

#include <unistd.h>

#include "catena/io/atomic_file.hpp"

#include "catena/core/error.hpp"
#include "catena/core/mpi_comm.hpp"

namespace catena::io {

void throw_if_any_rank_failed(MPI_Comm comm, const std::string& local_error) {
  const int n_ranks = mpi_size(comm);
  const int my_candidate = local_error.empty() ? n_ranks : mpi_rank(comm);
  int first_failed_rank = n_ranks;
  MPI_Allreduce(&my_candidate, &first_failed_rank, 1, MPI_INT, MPI_MIN, comm);
  if (first_failed_rank == n_ranks) return;

  std::string message = local_error;
  broadcast_string(comm, message, first_failed_rank);
  if (n_ranks > 1) message += " (on rank " + std::to_string(first_failed_rank) + ")";
  throw Error(message);
}

std::string current_exception_message() {
  try {
    throw;
  } catch (const std::exception& e) {
    return e.what()[0] != '\0' ? e.what() : "unnamed std::exception";
  } catch (...) {
    return "unknown exception";
  }
}

void fsync_once_per_node(MPI_Comm comm, const std::filesystem::path& path) {
  MPI_Comm node_comm = MPI_COMM_NULL;
  MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node_comm);
  int node_rank = 0;
  MPI_Comm_rank(node_comm, &node_rank);
  MPI_Comm_free(&node_comm);
  run_collective_phase(comm, [&] {
    if (node_rank == 0) fsync_path(path);
  });
}

namespace {

std::filesystem::path root_named_sibling(MPI_Comm comm, const std::filesystem::path& target) {
  long long root_pid = static_cast<long long>(::getpid());
  MPI_Bcast(&root_pid, 1, MPI_LONG_LONG, 0, comm);
  return temporary_sibling(target, static_cast<pid_t>(root_pid));
}

}  // namespace

CollectiveTemporary::CollectiveTemporary(MPI_Comm comm, const std::filesystem::path& target)
    : path(root_named_sibling(comm, target)) {
  if (mpi_rank(comm) == 0) owner.emplace(path);
}

void publish_written_file(MPI_Comm comm, CollectiveTemporary& temporary,
                          const std::filesystem::path& path) {
  fsync_once_per_node(comm, temporary.path);
  run_collective_phase(comm, [&] {
    if (!temporary.owner) return;
    rename_into_place(temporary.owner->path(), path);
    temporary.owner->release();
    fsync_path(path.has_parent_path() ? path.parent_path() : std::filesystem::path("."));
  });
}

}  // namespace catena::io
