// The initial acceleration M a = −f (solvers/time/consistent_acceleration.hpp) of a system
// without constraints, factored without pivoting (PETSc's LU on one rank, the interface
// Schur split on more), on 1, 2 and 3 ranks: a satisfies the equation to round-off, and a
// free node without mass is an error that names the cause on every rank, not a NaN.
#include <gtest/gtest.h>

#include <string>

#include "catena/assembly/petsc_call.hpp"
#include "catena/assembly/second_order_system.hpp"
#include "catena/core/error.hpp"
#include "catena/solvers/time/consistent_acceleration.hpp"
#include "model_builders.hpp"
#include "petsc_test_session.hpp"

namespace model = catena::model;

namespace {

model::Model cable_line() {
  return catena::test::cable_line_with_items({1.8e7, 195.0, 1.35, 0.0, 20000.0 / 1.8e7, {}}, 0.0);
}

}  // namespace

TEST(ConsistentAcceleration, SatisfiesTheEquationOfMotion) {
  catena::test::ensure_petsc();
  const model::Model m = cable_line();
  catena::assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
  catena::VecHandle q = system.create_vector(), v = system.create_vector(),
                    a = system.create_vector(), f = system.create_vector(),
                    r = system.create_vector();
  system.reference_state(q.get());  // not an equilibrium: the wire sags under gravity
  CATENA_PETSC(VecSet(v.get(), 0.0));
  catena::MatHandle M = system.create_matrix();
  system.jacobian({q.get(), nullptr, {}}, {0.0, 0.0, 1.0}, M.get());
  catena::solvers::consistent_acceleration(system, M.get(), 0.0, q.get(), v.get(), a.get());
  system.force({q.get(), v.get(), {}, 0.0}, f.get());
  CATENA_PETSC(MatMult(M.get(), a.get(), r.get()));
  CATENA_PETSC(VecAXPY(r.get(), 1.0, f.get()));  // M a + f
  PetscReal scale = 0.0, residual = 0.0, largest = 0.0;
  CATENA_PETSC(VecNorm(f.get(), NORM_INFINITY, &scale));
  CATENA_PETSC(VecNorm(r.get(), NORM_INFINITY, &residual));
  CATENA_PETSC(VecNorm(a.get(), NORM_INFINITY, &largest));
  EXPECT_GT(scale, 0.0);
  EXPECT_GT(largest, 1.0);  // gravity's 9.81 m/s² at least, more where the tension pulls
  EXPECT_LE(residual, 1e-11 * scale);
}

TEST(ConsistentAcceleration, FreeNodeWithoutMassIsNamed) {
  catena::test::ensure_petsc();
  model::Model m = cable_line();
  // A massless bar hanging from a pin: its free end has neither mass nor anything else
  // that gives it one.
  model::BarProps bar;
  bar.EA = 1e6;
  const auto ends = catena::test::add_line(m, {0, 5, 0}, {0, 5, -1}, 1, bar);
  catena::test::pin(m, ends.front());
  catena::assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
  catena::VecHandle q = system.create_vector(), v = system.create_vector(),
                    a = system.create_vector();
  system.reference_state(q.get());
  CATENA_PETSC(VecSet(v.get(), 0.0));
  catena::MatHandle M = system.create_matrix();
  system.jacobian({q.get(), nullptr, {}}, {0.0, 0.0, 1.0}, M.get());
  try {
    catena::solvers::consistent_acceleration(system, M.get(), 0.0, q.get(), v.get(), a.get());
    FAIL() << "expected a NumericalError";
  } catch (const catena::NumericalError& e) {
    const std::string text = e.what();
    EXPECT_NE(text.find("the mass matrix is singular"), std::string::npos) << text;
    EXPECT_NE(text.find("need a point mass"), std::string::npos) << text;
  }
}
