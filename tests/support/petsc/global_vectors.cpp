#include "global_vectors.hpp"

#include <cmath>

#include "catena/assembly/petsc_call.hpp"

namespace catena::test {

void add_wave(Vec x, double amplitude, double k, double phase) {
  PetscInt lo = 0, hi = 0;
  CATENA_PETSC(VecGetOwnershipRange(x, &lo, &hi));
  for (PetscInt i = lo; i < hi; ++i)
    CATENA_PETSC(
        VecSetValue(x, i, amplitude * std::sin(k * static_cast<double>(i) + phase), ADD_VALUES));
  CATENA_PETSC(VecAssemblyBegin(x));
  CATENA_PETSC(VecAssemblyEnd(x));
}

double max_abs(Vec x) {
  PetscReal m = 0.0;
  CATENA_PETSC(VecNorm(x, NORM_INFINITY, &m));
  return m;
}

}  // namespace catena::test
