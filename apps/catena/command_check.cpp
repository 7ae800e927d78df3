#include <cstdio>

#include "catena/core/mpi_comm.hpp"
#include "catena/model/model_summary.hpp"
#include "commands.hpp"
#include "scene_loading.hpp"

namespace catena::app {

void command_check(MPI_Comm comm, const CommandLine& cl) {
  const model::Model m = load_scene(comm, cl.scene, cl.overrides, memory_budget(comm, cl));
  if (mpi_rank(comm) == 0) {
    std::printf("%s: valid\n%s", cl.scene.c_str(), model::describe(m, mpi_size(comm)).c_str());
    if (cl.ids) std::printf("%s", model::describe_catenary_ids(m).c_str());
    std::fflush(stdout);
  }
}

}  // namespace catena::app
