#include "scene_loading.hpp"

#include <fstream>
#include <sstream>

#include "catena/core/error.hpp"
#include "catena/core/mpi_comm.hpp"
#include "catena/model/scene_reader.hpp"

namespace catena::app {
namespace {
constexpr std::streamoff kMaxSceneBytes = 64LL << 20;
}

model::MemoryBudget memory_budget(MPI_Comm comm, const CommandLine& cl) {
  model::MemoryBudget budget;
  budget.ranks = mpi_size(comm);
  MPI_Comm host = MPI_COMM_NULL;
  MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &host);
  int on_host = 1;
  MPI_Comm_size(host, &on_host);
  MPI_Comm_free(&host);
  MPI_Allreduce(&on_host, &budget.ranks_on_host, 1, MPI_INT, MPI_MAX, comm);
  if (cl.memory_limit_gib) {
    budget.host_bytes = *cl.memory_limit_gib * 1024.0 * 1024.0 * 1024.0;
    budget.from_option = true;
  } else {
    const double mine = model::physical_memory_bytes();
    MPI_Allreduce(&mine, &budget.host_bytes, 1, MPI_DOUBLE, MPI_MIN, comm);
  }
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
