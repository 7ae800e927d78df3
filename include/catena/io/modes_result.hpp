#pragma once
// The vibration modes of a model about its static equilibrium, as `catena modes` writes
// them: one HDF5 file (format "catena-modes-1", docs/output.md "Modes") with the mesh, the
// equilibrium and one shape per mode, and an XDMF file that ParaView opens with the modes
// as its time steps (step k = mode k).
#include <mpi.h>

#include <string>
#include <vector>

#include "catena/io/static_result.hpp"
#include "catena/model/model.hpp"

namespace catena::io {

struct ModesResult {
  std::vector<int> owned_nodes;   // model node indices this rank holds, ascending
  std::vector<double> positions;  // m, 3 per owned node: the equilibrium
  std::vector<double> frequency;  // Hz per mode, ascending
  // Per mode, 3 per owned node: the nodal displacement of the mass-normalised shape
  // (φᵀ M φ = 1 kg, so in m/√kg; fixed DOFs 0).
  std::vector<std::vector<double>> shapes;
};

// Collective. Writes `path` (and its .xmf) atomically: a temporary sibling renamed into
// place, so an existing file is replaced whole or not at all. Throws OutputError on every
// rank when it cannot.
void write_modes(MPI_Comm comm, const std::string& path, const model::Model& model,
                 const ModesResult& result, const RunInfo& info);

}  // namespace catena::io
