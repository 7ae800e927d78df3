#include "scene_loading.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "catena/core/error.hpp"
#include "catena/core/mpi_comm.hpp"
#include "catena/model/scene_reader.hpp"

namespace catena::app {
namespace {
constexpr std::streamoff kMaxSceneBytes = 64LL << 20;

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
  // Other runs of the job (a study's other groups, --error-bar-ranks' comparisons) share
  // the host: this run may use its ranks' part of it, the smallest part on any host.
  const int job_on_host = std::max(job_ranks_on_this_host, on_host);
  const double share = static_cast<double>(on_host) / job_on_host;
  double smallest_share = share;
  MPI_Allreduce(&share, &smallest_share, 1, MPI_DOUBLE, MPI_MIN, comm);
  if (smallest_share < 1.0) {
    const int mine = share == smallest_share ? job_on_host : 0;
    MPI_Allreduce(&mine, &budget.job_ranks_on_host, 1, MPI_INT, MPI_MAX, comm);
  }
  if (cl.memory_limit_gib) {
    budget.host_bytes = *cl.memory_limit_gib * 1024.0 * 1024.0 * 1024.0;
    budget.from_option = true;
  } else {
    const double mine = model::physical_memory_bytes();
    MPI_Allreduce(&mine, &budget.host_bytes, 1, MPI_DOUBLE, MPI_MIN, comm);
  }
  budget.host_bytes *= smallest_share;
  return budget;
}

model::Model load_scene(MPI_Comm comm, const std::string& path,
                        const std::vector<std::string>& overrides,
                        const model::MemoryBudget& budget) {
  std::string text, error;
  if (mpi_rank(comm) == 0) {
    try {
      std::ifstream in(path, std::ios::binary | std::ios::ate);
      if (!in) throw InputError({path, 0, ""}, "cannot open the scene file (does it exist?)");
      const std::streamoff size = in.tellg();
      if (size > kMaxSceneBytes)
        throw InputError({path, 0, ""}, "the scene file is " + std::to_string(size) +
                                            " bytes; at most 64 MiB is accepted");
      in.seekg(0);
      std::ostringstream os;
      os << in.rdbuf();
      text = os.str();
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
