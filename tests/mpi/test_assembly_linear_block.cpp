// The linear structure's assembled block (SecondOrderSystem::linearize_elements), on 1, 2
// and 3 ranks, against the nonlinear system's own tangent: with every cable linearised
// about q0, the residual at any (q, v) must be f(q0) + K(q0) (q − q0) + C(q0) v and the
// Newton matrix c_K K(q0) + c_C C(q0) + c_M M, with f, K, C, M from a second system that
// was never linearised. The line carries Kelvin–Voigt and Rayleigh damping, point masses
// (outside the block) and an elastic support, so the block's products and the per-item
// loop both take part.
#include <gtest/gtest.h>

#include "catena/assembly/petsc_call.hpp"
#include "catena/assembly/second_order_system.hpp"
#include "global_vectors.hpp"
#include "model_builders.hpp"
#include "petsc_test_session.hpp"

namespace model = catena::model;

namespace {

model::Model damped_line() {
  model::CableProps cw{1.8e7, 195.0, 1.35, 1e-3, 20000.0 / 1.8e7, {}};
  cw.rayleigh = {0.06, 7.6e-5};
  return catena::test::cable_line_with_items(cw, 5.0);
}

double norm(Mat A) {
  PetscReal n = 0.0;
  CATENA_PETSC(MatNorm(A, NORM_INFINITY, &n));
  return n;
}

}  // namespace

TEST(LinearBlock, ResidualAndMatrixAreTheNonlinearTangentsAtQ0) {
  catena::test::ensure_petsc();
  const model::Model m = damped_line();
  catena::assembly::SecondOrderSystem linear(MPI_COMM_WORLD, m), exact(MPI_COMM_WORLD, m);
  catena::VecHandle q0 = linear.create_vector(), q = linear.create_vector(),
                    v = linear.create_vector(), dq = linear.create_vector();
  linear.reference_state(q0.get());
  CATENA_PETSC(VecSet(dq.get(), 0.0));
  CATENA_PETSC(VecSet(v.get(), 0.0));
  catena::test::add_wave(dq.get(), 2e-3, 0.7, 0.0);
  catena::test::add_wave(v.get(), 0.3, 0.7, 1.0);
  CATENA_PETSC(VecWAXPY(q.get(), 1.0, dq.get(), q0.get()));

  int n = linear.linearize_elements(q0.get(), [&](int e) {
    return std::holds_alternative<model::CableProps>(*m.elements[static_cast<size_t>(e)].props);
  });
  MPI_Allreduce(MPI_IN_PLACE, &n, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_EQ(n, 24);

  // The nonlinear system's f, K, C at (q0, v = 0) and M.
  catena::VecHandle f0 = exact.create_vector(), expected = exact.create_vector(),
                    got = linear.create_vector();
  exact.force({q0.get(), nullptr, {}}, f0.get());
  catena::MatHandle K = exact.create_matrix(), C = exact.create_matrix(), M = exact.create_matrix();
  exact.tangent_parts({q0.get(), nullptr, {}}, K.get(), C.get());
  exact.jacobian({q0.get(), nullptr, {}}, {0.0, 0.0, 1.0}, M.get());

  // Residual: f0 + K dq + C v.
  CATENA_PETSC(MatMultAdd(K.get(), dq.get(), f0.get(), expected.get()));
  CATENA_PETSC(MatMultAdd(C.get(), v.get(), expected.get(), expected.get()));
  double scale = 0.0;
  linear.force({q.get(), v.get(), {}}, got.get(), &scale);
  EXPECT_GT(scale, 0.0);
  const double size = catena::test::max_abs(expected.get());
  CATENA_PETSC(VecAXPY(got.get(), -1.0, expected.get()));
  EXPECT_GT(size, 1.0);
  EXPECT_LE(catena::test::max_abs(got.get()), 1e-9 * size) << "|f| " << size;

  // Newton matrix with every coefficient in play.
  const catena::assembly::JacobianCoefficients c{0.7, 0.3, 2.0e4, 0.0, 0.0};
  catena::MatHandle J = linear.create_matrix(), want = exact.create_matrix();
  linear.jacobian({q.get(), v.get(), {}}, c, J.get());
  CATENA_PETSC(MatZeroEntries(want.get()));
  CATENA_PETSC(MatAXPY(want.get(), c.c_K, K.get(), SAME_NONZERO_PATTERN));
  CATENA_PETSC(MatAXPY(want.get(), c.c_C, C.get(), SAME_NONZERO_PATTERN));
  CATENA_PETSC(MatAXPY(want.get(), c.c_M, M.get(), SAME_NONZERO_PATTERN));
  const double matrix_size = norm(want.get());
  CATENA_PETSC(MatAXPY(J.get(), -1.0, want.get(), SAME_NONZERO_PATTERN));
  EXPECT_LE(norm(J.get()), 1e-12 * matrix_size) << "|J| " << matrix_size;

  // tangent_parts gives the block's K and C alone.
  catena::MatHandle K_linear = linear.create_matrix(), C_linear = linear.create_matrix();
  linear.tangent_parts({q.get(), v.get(), {}}, K_linear.get(), C_linear.get());
  CATENA_PETSC(MatAXPY(K_linear.get(), -1.0, K.get(), SAME_NONZERO_PATTERN));
  CATENA_PETSC(MatAXPY(C_linear.get(), -1.0, C.get(), SAME_NONZERO_PATTERN));
  EXPECT_LE(norm(K_linear.get()), 1e-12 * norm(K.get()));
  EXPECT_LE(norm(C_linear.get()), 1e-12 * norm(C.get()));
}
