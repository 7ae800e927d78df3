#include "run_info.hpp"

#include <petscsys.h>

#include "catena/core/mpi_comm.hpp"
#include "catena/core/version.hpp"

namespace catena::app {
namespace {

// PETSc options in force, without the app's own flags (PETSc also stores those, having
// seen them on the command line).
std::string petsc_options_text() {
  for (const char* own : {"-o", "--output", "--set", "-h", "--help"})
    PetscOptionsClearValue(nullptr, own);
  char* text = nullptr;
  if (PetscOptionsGetAll(nullptr, &text) != 0 || !text) return "";
  std::string s(text);
  PetscFree(text);
  return s;
}

}  // namespace

std::string code_version() { return std::string(version()) + " (" + git_version() + ")"; }

io::RunInfo run_info(const CommandLine& cl, const assembly::SecondOrderSystem& system) {
  io::RunInfo info;
  info.code_version = code_version();
  info.command_line = cl.joined;
  info.petsc_options = petsc_options_text();
  info.n_ranks = mpi_size(system.comm());
  info.n_dofs = static_cast<int>(system.dof_map().n_global());
  return info;
}

}  // namespace catena::app
