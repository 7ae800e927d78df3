#include "run_environment.hpp"

#include <petscsys.h>

#include <algorithm>
#include <cstdio>

#include "catena/assembly/petsc_call.hpp"
#include "catena/core/version.hpp"
#include "catena/io/hdf5_library.hpp"

namespace catena::app {

std::string version_text() {
  char petsc[256] = {};
  CATENA_PETSC(PetscGetVersion(petsc, sizeof petsc));
  char mpi[MPI_MAX_LIBRARY_VERSION_STRING] = {};
  int length = 0;
  MPI_Get_library_version(mpi, &length);
  std::string mpi_line(mpi, static_cast<std::size_t>(std::max(length, 0)));
  mpi_line = mpi_line.substr(0, mpi_line.find_first_of("\n,"));  // the first clause
  return std::string("catena ") + version() + " (commit " + git_version() + ")\n" + petsc + "\n" +
         mpi_line + "\nHDF5 " + io::hdf5_version() + "\n";
}

void warn_unused_petsc_options(int rank, const std::vector<std::string>& given) {
  if (rank != 0 || given.empty()) return;
  PetscInt n = 0;
  char** names = nullptr;
  char** values = nullptr;
  CATENA_PETSC(PetscOptionsLeftGet(nullptr, &n, &names, &values));
  for (PetscInt k = 0; k < n; ++k) {
    std::string name = names[k] ? names[k] : "";
    if (name.empty() || name[0] != '-') name = "-" + name;
    if (std::find(given.begin(), given.end(), name) == given.end()) continue;
    std::fprintf(stderr,
                 "catena: warning: PETSc option %s was not used: misspelt, or for a solver "
                 "this command does not create (catena --help lists the solvers' prefixes)\n",
                 name.c_str());
  }
  CATENA_PETSC(PetscOptionsLeftRestore(nullptr, &n, &names, &values));
  std::fflush(stderr);
}

}  // namespace catena::app
