// AlgebraicPart's Newton convergence measure: constraint rows weighted by
// w = atol / (atol + floor), nodal rows as they are, for the plain and the interleaved
// (IRK stage) layout; the 2-norm (no measure) when there is no floor.
#include <gtest/gtest.h>

#include <cmath>

#include "catena/assembly/petsc_call.hpp"
#include "catena/assembly/second_order_system.hpp"
#include "catena/solvers/time/algebraic_part.hpp"
#include "model_builders.hpp"
#include "petsc_test_session.hpp"

namespace solvers = catena::solvers;

namespace {

TEST(AlgebraicPart, ResidualMeasureWeighsTheConstraintRowsDown) {
  catena::test::ensure_petsc();
  // The cable pendulum held by a driven pivot constraint: three multipliers.
  const catena::model::Model m = catena::test::cable_pendulum(8, true);
  catena::assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
  catena::VecHandle q = system.create_vector();
  system.reference_state(q.get());
  catena::MatHandle mass = system.create_matrix();
  system.jacobian({q.get(), nullptr, {}}, {0.0, 0.0, 1.0}, mass.get());
  const solvers::AlgebraicPart algebraic(system, mass.get());
  ASSERT_TRUE(algebraic.active());
  EXPECT_FALSE(algebraic.residual_measure(1.0, 0.0)) << "no floor: the plain 2-norm";

  PetscInt n_local = 0, n_global = 0;
  CATENA_PETSC(VecGetLocalSize(algebraic.mask(), &n_local));
  CATENA_PETSC(VecGetSize(algebraic.mask(), &n_global));
  PetscScalar n_algebraic = 0.0;
  CATENA_PETSC(VecSum(algebraic.mask(), &n_algebraic));
  ASSERT_EQ(n_algebraic, 3.0);
  const double atol = 1e-8, floor = 3e-8, weight = 0.25;  // w = atol / (atol + floor)
  for (int blocks : {1, 3}) {
    // Nodal entries 2, constraint entries 5, `blocks` entries per DOF.
    catena::VecHandle r;
    CATENA_PETSC(VecCreateMPI(MPI_COMM_WORLD, blocks * n_local, PETSC_DETERMINE, r.out()));
    PetscScalar* x = nullptr;
    const PetscScalar* mask = nullptr;
    CATENA_PETSC(VecGetArray(r.get(), &x));
    CATENA_PETSC(VecGetArrayRead(algebraic.mask(), &mask));
    for (PetscInt i = 0; i < n_local; ++i)
      for (int b = 0; b < blocks; ++b) x[blocks * i + b] = mask[i] != 0.0 ? 5.0 : 2.0;
    CATENA_PETSC(VecRestoreArrayRead(algebraic.mask(), &mask));
    CATENA_PETSC(VecRestoreArray(r.get(), &x));
    const auto measure = algebraic.residual_measure(atol, floor, blocks);
    ASSERT_TRUE(measure);
    const double nodal = static_cast<double>(n_global) - n_algebraic;
    const double expected =
        std::sqrt(blocks * (4.0 * nodal + weight * weight * 25.0 * n_algebraic));
    EXPECT_NEAR(measure(r.get()), expected, 1e-13 * expected) << blocks << " blocks";
  }
}

}  // namespace
