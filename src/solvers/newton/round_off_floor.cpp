#include "catena/solvers/newton/round_off_floor.hpp"

#include <limits>

#include "catena/assembly/petsc_call.hpp"

namespace catena::solvers {

void RoundOffFloor::set_tangent(Mat K) {
  if (!diagonal_.get()) {
    CATENA_PETSC(MatCreateVecs(K, diagonal_.out(), nullptr));
    CATENA_PETSC(VecDuplicate(diagonal_.get(), work_.out()));
  }
  CATENA_PETSC(MatGetDiagonal(K, diagonal_.get()));
}

double RoundOffFloor::at(Vec q) {
  if (!diagonal_.get()) return 0.0;
  CATENA_PETSC(VecPointwiseMult(work_.get(), diagonal_.get(), q));
  PetscReal norm = 0.0;
  CATENA_PETSC(VecNorm(work_.get(), NORM_2, &norm));
  return 2.0 * std::numeric_limits<double>::epsilon() * norm;
}

}  // namespace catena::solvers
