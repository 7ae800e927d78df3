#pragma once
// Parallel HDF5 output of a static solution (+ an XDMF file beside it for ParaView).
// Layout and units: docs/output.md.
#include <mpi.h>

#include <string>

#include "catena/io/static_result.hpp"
#include "catena/model/model.hpp"

namespace catena::io {

// Collective. Writes `path` (and path with .xmf) atomically: the data go to a temporary
// file that is renamed into place only when complete, so a failure never leaves a half file.
// On failure throws catena::OutputError on every rank ("cannot write '<path>': <why>").
void write_static_result(MPI_Comm comm, const std::string& path, const model::Model& model,
                         const StaticResult& result, const RunInfo& info);

}  // namespace catena::io
