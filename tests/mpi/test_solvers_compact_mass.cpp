// The compact mass matrix HHT multiplies in every residual (assembly/compact_matrix.hpp)
// and the system's damping flag (SecondOrderSystem::has_damping), on 1, 2 and 3 ranks:
// the compact copy holds only the mass's nonzeros and gives the full matrix's product
// to round-off (1e-14 relative: only the order of the additions differs); the damping
// flag is false exactly when no kernel damps, and then C assembles to zero.
#include <gtest/gtest.h>

#include "catena/assembly/compact_matrix.hpp"
#include "catena/assembly/petsc_call.hpp"
#include "catena/assembly/second_order_system.hpp"
#include "global_vectors.hpp"
#include "model_builders.hpp"
#include "petsc_test_session.hpp"

namespace model = catena::model;

namespace {

// A 60 m cable line (20 kN) with point masses and an elastic support; `tau`: its
// Kelvin–Voigt damping time.
model::Model cable_line(double tau) {
  return catena::test::cable_line_with_items({1.8e7, 195.0, 1.35, tau, 20000.0 / 1.8e7, {}}, 0.0);
}

double nonzeros(Mat A) {
  MatInfo info;
  CATENA_PETSC(MatGetInfo(A, MAT_GLOBAL_SUM, &info));
  return info.nz_used;
}

}  // namespace

TEST(CompactMass, SameProductFewerEntries) {
  catena::test::ensure_petsc();
  const model::Model m = cable_line(0.0);
  catena::assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
  catena::VecHandle q = system.create_vector(), x = system.create_vector(),
                    full = system.create_vector(), compact = system.create_vector();
  system.reference_state(q.get());
  catena::MatHandle M = system.create_matrix();
  system.jacobian({q.get(), nullptr, {}}, {0.0, 0.0, 1.0}, M.get());
  const catena::MatHandle C = catena::assembly::compact_copy(M.get());

  // A partition-independent x: a function of the global index.
  CATENA_PETSC(VecSet(x.get(), 0.3));
  catena::test::add_wave(x.get(), 1.0, 0.7, 0.0);
  CATENA_PETSC(MatMult(M.get(), x.get(), full.get()));
  CATENA_PETSC(MatMult(C.get(), x.get(), compact.get()));
  PetscReal scale = 0.0, diff = 0.0;
  CATENA_PETSC(VecNorm(full.get(), NORM_INFINITY, &scale));
  CATENA_PETSC(VecAXPY(compact.get(), -1.0, full.get()));
  CATENA_PETSC(VecNorm(compact.get(), NORM_INFINITY, &diff));
  EXPECT_GT(scale, 0.0);
  EXPECT_LE(diff, 1e-14 * scale);
  // Cable rows couple only equal components (S ⊗ I₃): at most a third of the pattern.
  const double ratio = nonzeros(C.get()) / nonzeros(M.get());
  EXPECT_GT(ratio, 0.0);
  EXPECT_LT(ratio, 0.4);
}

TEST(SystemDamping, FlagMatchesTheAssembledC) {
  catena::test::ensure_petsc();
  for (double tau : {0.0, 1e-3}) {
    const model::Model m = cable_line(tau);
    catena::assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
    EXPECT_EQ(system.has_damping(), tau != 0.0) << "tau " << tau;
    catena::VecHandle q = system.create_vector(), v = system.create_vector();
    system.reference_state(q.get());
    CATENA_PETSC(VecSet(v.get(), 0.01));
    catena::MatHandle K = system.create_matrix(), C = system.create_matrix();
    system.tangent_parts({q.get(), v.get(), {}}, K.get(), C.get());
    PetscReal norm = 0.0;
    CATENA_PETSC(MatNorm(C.get(), NORM_FROBENIUS, &norm));
    EXPECT_EQ(norm > 0.0, system.has_damping()) << "tau " << tau << ", |C| " << norm;
  }
}
