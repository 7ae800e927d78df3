#pragma once
#include <mpi.h>

#include <string>
#include <vector>

#include "catena/model/model.hpp"

namespace catena::app {

// Collective. Rank 0 reads and checks the file, every rank parses the same text, so all
// ranks hold the same Model or all throw the same InputError.
model::Model load_scene(MPI_Comm comm, const std::string& path,
                        const std::vector<std::string>& overrides);

}  // namespace catena::app
