#include "catena/solvers/consistent_acceleration.hpp"

#include "catena/assembly/petsc_call.hpp"
#include "catena/core/error.hpp"
#include "catena/solvers/direct_newton.hpp"
#include "catena/solvers/mumps_status.hpp"

namespace catena::solvers {

void consistent_acceleration(assembly::SecondOrderSystem& system, Mat mass, double t, Vec q,
                             Vec v, Vec a) {
  VecHandle rhs = system.create_vector();
  system.force({q, v, {}, t}, rhs.get());
  CATENA_PETSC(VecScale(rhs.get(), -1.0));
  KspHandle ksp = create_direct_ksp(system.comm(), "mass_", JacobianSymmetry::symmetric);
  CATENA_PETSC(KSPSetOperators(ksp.get(), mass, mass));
  CATENA_PETSC(KSPSolve(ksp.get(), rhs.get(), a));
  const MumpsStatus mumps = mumps_status(ksp.get());
  KSPConvergedReason reason;
  CATENA_PETSC(KSPGetConvergedReason(ksp.get(), &reason));
  if (mumps.null_pivots > 0 || mumps.infog1 < 0 || reason < 0)
    throw NumericalError(
        "the mass matrix is singular (" + std::to_string(mumps.null_pivots) +
        " null pivots, MUMPS INFOG(1) = " + std::to_string(mumps.infog1) +
        "): every free DOF needs mass; massless nodes (e.g. joined only by massless bars "
        "or springs) need a point mass");
}

}  // namespace catena::solvers
