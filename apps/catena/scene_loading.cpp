#include "scene_loading.hpp"

#include <algorithm>

#include "catena/core/error.hpp"
#include "catena/core/mpi_comm.hpp"
#include "catena/model/scene_reader.hpp"

namespace catena::app {
namespace {
// Collective. The ranks of `comm` on this rank's host (MPI shared-memory group).
int ranks_on_this_host(MPI_Comm comm) {
  MPI_Comm host = MPI_COMM_NULL;
  MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &host);
  int on_host = 1;
  MPI_Comm_size(host, &on_host);
  MPI_Comm_free(&host);
  return on_host;
}

int job_ranks_on_this_host = 1;  // record_job_layout's
}  // namespace

void record_job_layout(MPI_Comm world) { job_ranks_on_this_host = ranks_on_this_host(world); }

model::MemoryBudget memory_budget(MPI_Comm comm, const CommandLine& cl) {
  model::MemoryBudget budget;
  budget.ranks = mpi_size(comm);
  const int on_host = ranks_on_this_host(comm);
  MPI_Allreduce(&on_host, &budget.ranks_on_host, 1, MPI_INT, MPI_MAX, comm);
  // Other runs of the job (a study's other groups, --error-bar-ranks' comparisons) may share
  // a host: each of the job's ranks there may use its part of the host's memory, and the
  // run its ranks' parts. The smallest part per rank on any host, times the ranks of the run
  // on its fullest host, is the budget that host's need is compared with.
  const int job_on_host = std::max(job_ranks_on_this_host, on_host);
  double host = 0.0;
  if (cl.memory_limit_gib) {
    host = *cl.memory_limit_gib * 1024.0 * 1024.0 * 1024.0;
    budget.from_option = true;
  } else {
    host = model::physical_memory_bytes();
  }
  const double mine = host / job_on_host;
  double per_rank = mine;
  MPI_Allreduce(&mine, &per_rank, 1, MPI_DOUBLE, MPI_MIN, comm);
  budget.host_bytes = per_rank * budget.ranks_on_host;
  int shared = on_host < job_on_host ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &shared, 1, MPI_INT, MPI_MAX, comm);
  if (shared) {
    // The job's ranks on the run's fullest host, for the message.
    const int there = on_host == budget.ranks_on_host ? job_on_host : 0;
    MPI_Allreduce(&there, &budget.job_ranks_on_host, 1, MPI_INT, MPI_MAX, comm);
  }
  return budget;
}

model::Model load_scene(MPI_Comm comm, const std::string& path,
                        const std::vector<std::string>& overrides,
                        const model::MemoryBudget& budget) {
  std::string text, error;
  if (mpi_rank(comm) == 0) {
    try {
      text = model::read_scene_file(path);
      model::check_scene_text(text, path);
    } catch (const InputError& e) {
      error = e.what();
    }
  }
  broadcast_string(comm, error);
  if (!error.empty()) throw InputError({}, error);
  broadcast_string(comm, text);
  model::Model m = model::parse_scene(text, path, overrides, budget);
  return m;
}

}  // namespace catena::app
