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

model::Model load_scene(MPI_Comm comm, const std::string& path,
                        const std::vector<std::string>& overrides) {
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
  model::Model m = model::parse_scene(text, path, overrides);
  return m;
}

}  // namespace catena::app
