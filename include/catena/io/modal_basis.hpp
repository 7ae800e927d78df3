#pragma once
// A modal basis: the catenary's modes that a modal run (analysis.structure: modal) computed,
// kept in a file so that later runs of the same structure — a speed sweep, other
// pantographs, a restart — skip the eigen-solve (analysis.modal_basis: FILE;
// docs/output.md, "Modal basis"). The file holds the modes only; what depends on more
// than K and M (damping, loads, sites, static correction) every run derives anew, and
// every run checks the modes against its own K and M before it uses them
// (solvers/modes/modes_check.hpp, called by the app's modal set-up).
//
// HDF5, format "catena-modal-basis-1", written by all ranks through MPI-IO and renamed
// into place (atomic):
//   /frequency          n_modes, Hz, ascending: every mode below cutoff_hz
//   /shapes/mode_<k>    n_rows each (k = 1 .. n_modes): mode k (unit modal mass: 1/√kg
//                       for positions, 1/(√kg·m) for slopes) at the free unknowns in node
//                       order — nodes
//                       ascending, each node's unknowns in its kind's layout
//                       (model/unknown_kinds.hpp), a slope held in direction once — so the
//                       file does not depend on the number of ranks
//   attributes          format, cutoff_hz, n_modes, n_rows, n_nodes, n_elements, scene_file,
//                       code_version
#include <mpi.h>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "catena/model/model.hpp"

namespace catena::io {

// How the rows of a basis are spread over the ranks: this rank's rows (node order,
// strictly ascending) among n_rows.
struct BasisRows {
  std::int64_t n_rows = 0;
  std::vector<int> owned;
};

struct ModalBasis {
  double cutoff_hz = 0.0;         // as stored (≥ the cut-off asked for when read)
  std::vector<double> frequency;  // Hz, ascending
  // Per mode: the values of this rank's rows, in BasisRows::owned order.
  std::vector<std::vector<double>> shapes;
};

// Collective. Writes `path` atomically (shapes: per mode, this rank's rows' values). Throws
// catena::OutputError on every rank when it cannot.
void write_modal_basis(MPI_Comm comm, const std::string& path, const model::Model& model,
                       const BasisRows& rows, double cutoff_hz,
                       const std::vector<double>& frequency,
                       const std::vector<std::span<const double>>& shapes,
                       const std::string& code_version);

// Collective. The modes of `path` with frequency ≤ cutoff_hz, each rank its rows. Throws
// catena::InputError naming the file on every rank when it is not a modal basis, was
// written for a model with other node, element or unknown counts, or holds modes up to a
// lower cut-off than cutoff_hz.
ModalBasis read_modal_basis(MPI_Comm comm, const std::string& path, const model::Model& model,
                            const BasisRows& rows, double cutoff_hz);

}  // namespace catena::io
