#pragma once
// Before any solving: can the run create its output file and the checkpoint beside it?
// A missing directory found only when the results are written would cost the whole run.
#include <mpi.h>

#include <string>

#include "catena/model/model.hpp"

namespace catena::app {

// Not collective. Why `path` (and `path`.chk) cannot be created or overwritten, or "" if
// they can: "directory /x/y does not exist", "/x/f is a file, not a directory",
// "it is a directory", "permission denied" (from the system, for the directory or the
// file). Creates and removes a probe file in the directory: permission bits alone do not
// tell (root, read-only mounts, ACLs).
std::string output_path_problem(const std::string& path);

// Collective. Rank 0 checks m.output.file (set by the scene's output.file or by -o); every
// rank throws the same InputError naming the key, the path and the reason. A name ending in
// .xmf or .xmf2 (the XDMF companions') is refused for every analysis.
void check_output_path(MPI_Comm comm, const model::Model& m, bool from_command_line);

// Collective. The modal basis a modal run names (analysis.modal_basis), if any: a file to
// read, or one the run can create when it is not there yet (as output_path_problem);
// every rank throws the same InputError naming the key, the path and the reason.
void check_modal_basis_path(MPI_Comm comm, const model::Model& m);

}  // namespace catena::app
