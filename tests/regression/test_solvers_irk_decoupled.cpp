// The decoupled (RADAU5-style) stage linear algebra against the coupled s·n stage matrix:
//  - the operator: for the constrained pendulum's K, C, M + Gᵀ and scaled constraint rows,
//    the MATSHELL product equals the assembled coupled matrix's to 1e-13 relative, and the
//    decoupled solve inverts the coupled matrix (‖J⁻¹(Jx) − x‖ ≤ 1e-9 ‖x‖) for Radau IIA 3,
//    Gauss 2 and 3, Lobatto IIIC 3 and 4 (real blocks, complex blocks and both);
//  - the iteration: on the cable pendulum (8 ANCF cables, large rotation, simplified
//    Newton with its tangent refreshes) and on the same pendulum held by a driven pivot
//    constraint, a decoupled and a coupled integrator stepped side by side take the same
//    Newton iterations in every step and the same factorisations, and their states agree
//    to 1e-10 relative after every step (measured worst: q 8.6e-13, v 7.3e-11, Gauss 3
//    constrained; 64 steps of 3.9 ms);
//  - Radau IIA's error estimate solves with the real block's factorisation: the same
//    estimates (1e-8 relative), fewer factorisations, the same solves;
//  - the selection: auto decouples exactly where it is exact, and `decoupled` is an input
//    error for Lobatto IIIA, SDIRK and full Newton.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "catena/assembly/petsc_call.hpp"
#include "catena/assembly/second_order_system.hpp"
#include "catena/core/error.hpp"
#include "catena/solvers/time/algebraic_part.hpp"
#include "catena/solvers/time/irk/block_matrix.hpp"
#include "catena/solvers/time/irk/decoupled_stage_solver.hpp"
#include "catena/solvers/time/irk/interleaved_vectors.hpp"
#include "catena/solvers/time/irk/irk_integrator.hpp"
#include "dynamics_fixtures.hpp"
#include "model_builders.hpp"
#include "petsc_test_session.hpp"

namespace solvers = catena::solvers;
namespace model = catena::model;
using catena::Vec3;
using solvers::TableauFamily;

namespace {

// The pendulum of meshes/cable_pendulum.yaml; its pivot eliminated, or a constraint
// driven along x(t) = A (sin ωt − ωt) (zero velocity and acceleration at the start).
model::Model pendulum(bool driven_pivot) { return catena::test::cable_pendulum(8, driven_pivot); }

struct Method {
  TableauFamily family;
  int stages;
};
std::string label(const Method& m) { return solvers::make_tableau(m.family, m.stages).name; }

double max_abs(Vec x) {
  PetscReal n = 0.0;
  CATENA_PETSC(VecNorm(x, NORM_INFINITY, &n));
  return n;
}
double max_difference(Vec a, Vec b) {
  catena::VecHandle d;
  CATENA_PETSC(VecDuplicate(a, d.out()));
  CATENA_PETSC(VecWAXPY(d.get(), -1.0, b, a));
  return max_abs(d.get());
}

class Operator : public testing::TestWithParam<Method> {};

TEST_P(Operator, ShellProductAndSolveMatchTheCoupledMatrix) {
  catena::test::ensure_petsc();
  const Method method = GetParam();
  const auto tableau = solvers::make_tableau(method.family, method.stages);
  const int s = tableau.stages;
  const double h = 2e-3;
  const model::Model m = pendulum(true);
  catena::assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
  catena::VecHandle q = system.create_vector(), v = system.create_vector(),
                    noise = system.create_vector();
  system.reference_state(q.get());
  catena::PetscHandle<PetscRandom, PetscRandomDestroy> random;
  CATENA_PETSC(PetscRandomCreate(MPI_COMM_WORLD, random.out()));
  CATENA_PETSC(PetscRandomSetSeed(random.get(), 7));
  CATENA_PETSC(PetscRandomSeed(random.get()));
  CATENA_PETSC(VecSetRandom(noise.get(), random.get()));
  CATENA_PETSC(VecAXPY(q.get(), 0.01, noise.get()));  // a strained, rotated state
  CATENA_PETSC(VecSetRandom(v.get(), random.get()));
  catena::MatHandle K = system.create_matrix(), C = system.create_matrix(),
                    mass = system.create_matrix(), M = system.create_matrix();
  system.tangent_parts({q.get(), v.get(), {}, 0.1}, K.get(), C.get());
  system.jacobian({q.get(), nullptr, {}}, {0.0, 0.0, 1.0}, mass.get());
  system.jacobian({q.get(), nullptr, {}}, {0.0, 0.0, 1.0, 1.0, 0.0}, M.get());
  solvers::AlgebraicPart algebraic(system, mass.get());
  ASSERT_TRUE(algebraic.active());
  const double factor = algebraic.mass_scale() / (h * h);
  catena::VecHandle d = system.create_vector();
  CATENA_PETSC(VecSet(d.get(), 1.0));
  algebraic.scale_rows(d.get(), factor);

  // The coupled stage matrix, as IrkIntegrator builds it.
  const Eigen::MatrixXd A2 = solvers::a_squared(tableau);
  solvers::BlockMatrix coupled(mass.get(), s);
  solvers::BlockCoefficients c(s);
  for (int i = 0; i < s; ++i)
    for (int j = 0; j < s; ++j) {
      c.M(i, j) = i == j ? 1.0 : 0.0;
      c.C(i, j) = h * tableau.A(i, j);
      c.K(i, j) = h * h * A2(i, j);
    }
  coupled.assemble(K.get(), C.get(), M.get(), c);
  algebraic.scale_rows(coupled.matrix(), factor, s);

  const auto form = solvers::decompose_butcher_matrix(tableau.A);
  ASSERT_TRUE(form.has_value());
  solvers::DecoupledStageSolver decoupled(M.get(), tableau.A, A2, *form, "test_decoupled_");
  decoupled.assemble({K.get(), C.get(), M.get(), d.get(), h});

  catena::VecHandle x = coupled.create_vector(), y_coupled = coupled.create_vector(),
                    y_shell = coupled.create_vector(), back = coupled.create_vector();
  CATENA_PETSC(VecSetRandom(x.get(), random.get()));
  CATENA_PETSC(MatMult(coupled.matrix(), x.get(), y_coupled.get()));
  CATENA_PETSC(MatMult(decoupled.operator_matrix(), x.get(), y_shell.get()));
  const double product = max_difference(y_coupled.get(), y_shell.get()) / max_abs(y_coupled.get());
  ASSERT_TRUE(decoupled.solve(y_coupled.get(), back.get())) << decoupled.failure();
  const double inverse = max_difference(back.get(), x.get()) / max_abs(x.get());
  std::printf("  %s: shell product %.2e, decoupled solve of the coupled product %.2e (relative)\n",
              tableau.name.c_str(), product, inverse);
  EXPECT_LT(product, 1e-13);
  EXPECT_LT(inverse, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(
    Catena, Operator,
    testing::Values(Method{TableauFamily::radau_iia, 3}, Method{TableauFamily::gauss, 2},
                    Method{TableauFamily::gauss, 3}, Method{TableauFamily::lobatto_iiic, 3},
                    Method{TableauFamily::lobatto_iiic, 4}),
    [](const testing::TestParamInfo<Method>& param) { return label(param.param); });

// One integrator of the given linear algebra on its own system.
struct IntegratorRun {
  catena::assembly::SecondOrderSystem system;
  catena::VecHandle q, v;
  std::unique_ptr<solvers::IrkIntegrator> irk;
  IntegratorRun(const model::Model& m, const Method& method, solvers::StageLinearAlgebra algebra)
      : system(MPI_COMM_WORLD, m), q(system.create_vector()), v(system.create_vector()) {
    system.reference_state(q.get());
    solvers::IrkOptions o;
    o.family = method.family;
    o.stages = method.stages;
    o.atol = 1e-9;
    o.rtol = 1e-12;
    o.max_newton_iterations = 30;
    o.linear_algebra = algebra;
    irk = std::make_unique<solvers::IrkIntegrator>(system, o);
    irk->set_state(0.0, q.get(), v.get(), nullptr);
  }
};

void expect_same_iterates(const model::Model& m, const Method& method, int n_steps, double h) {
  IntegratorRun coupled(m, method, solvers::StageLinearAlgebra::coupled);
  IntegratorRun decoupled(m, method, solvers::StageLinearAlgebra::decoupled);
  ASSERT_FALSE(coupled.irk->decoupled());
  ASSERT_TRUE(decoupled.irk->decoupled());
  double worst_q = 0.0, worst_v = 0.0;
  int iterations = 0;
  for (int k = 0; k < n_steps; ++k) {
    const solvers::StepOutcome a = coupled.irk->attempt(h, nullptr);
    const solvers::StepOutcome b = decoupled.irk->attempt(h, nullptr);
    ASSERT_TRUE(a.converged) << "coupled, step " << k << ": " << a.failure;
    ASSERT_TRUE(b.converged) << "decoupled, step " << k << ": " << b.failure;
    EXPECT_EQ(a.newton_iterations, b.newton_iterations) << "step " << k;
    iterations += a.newton_iterations;
    coupled.irk->accept();
    decoupled.irk->accept();
    worst_q = std::max(
        worst_q, max_difference(coupled.irk->q(), decoupled.irk->q()) / max_abs(coupled.irk->q()));
    worst_v = std::max(
        worst_v, max_difference(coupled.irk->v(), decoupled.irk->v()) / max_abs(coupled.irk->v()));
  }
  const auto& cc = coupled.irk->counters();
  const auto& cd = decoupled.irk->counters();
  std::printf(
      "  %s%s: %d steps, %d Newton iterations, %ld factorisations, %ld tangents; worst "
      "relative difference q %.2e, v %.2e\n",
      label(method).c_str(), m.constraints.empty() ? "" : " (constrained)", n_steps, iterations,
      cd.factorizations, cd.jacobian_evaluations, worst_q, worst_v);
  EXPECT_LT(worst_q, 1e-10);
  EXPECT_LT(worst_v, 1e-10);
  EXPECT_EQ(cc.newton_iterations, cd.newton_iterations);
  EXPECT_EQ(cc.factorizations, cd.factorizations);
  EXPECT_EQ(cc.jacobian_evaluations, cd.jacobian_evaluations);
  // The tangent was refreshed, so the reuse logic ran (Radau IIA 5 contracts well enough
  // with its first tangent over the whole run: one factorisation).
  if (method.stages <= 3) {
    EXPECT_GT(cd.factorizations, 1);
  }
}

class SameIterates : public testing::TestWithParam<Method> {};

TEST_P(SameIterates, OnTheCablePendulum) {
  catena::test::ensure_petsc();
  expect_same_iterates(pendulum(false), GetParam(), 64, 0.25 / 64);
}

TEST_P(SameIterates, OnTheDrivenPendulumWithAConstraint) {
  catena::test::ensure_petsc();
  expect_same_iterates(pendulum(true), GetParam(), 64, 0.25 / 64);
}

INSTANTIATE_TEST_SUITE_P(
    Catena, SameIterates,
    testing::Values(Method{TableauFamily::radau_iia, 3}, Method{TableauFamily::radau_iia, 5},
                    Method{TableauFamily::gauss, 2}, Method{TableauFamily::gauss, 3},
                    Method{TableauFamily::lobatto_iiic, 3}),
    [](const testing::TestParamInfo<Method>& param) { return label(param.param); });

// Radau IIA's estimate filter M + hγ0 C + (hγ0)² K is the decoupled solve's real block:
// the decoupled integrator solves with that factorisation instead of its own, so it
// factors less and gives the same estimates (to round-off in the filter matrix).
TEST(DecoupledEstimate, RadauEstimateReusesTheRealBlock) {
  catena::test::ensure_petsc();
  const model::Model m = pendulum(false);
  const Method method{TableauFamily::radau_iia, 3};
  IntegratorRun coupled(m, method, solvers::StageLinearAlgebra::coupled);
  IntegratorRun decoupled(m, method, solvers::StageLinearAlgebra::decoupled);
  solvers::ErrorTolerance tol;
  tol.rtol = 1e-6;
  tol.atol = 1e-8;
  tol.reference = coupled.q.get();
  double worst = 0.0;
  for (int k = 0; k < 32; ++k) {
    const solvers::StepOutcome a = coupled.irk->attempt(0.25 / 64, &tol);
    const solvers::StepOutcome b = decoupled.irk->attempt(0.25 / 64, &tol);
    ASSERT_TRUE(a.converged && b.converged) << "step " << k;
    ASSERT_GT(a.error, 0.0);
    worst = std::max(worst, std::abs(a.error - b.error) / a.error);
    coupled.irk->accept();
    decoupled.irk->accept();
  }
  const auto& cc = coupled.irk->counters();
  const auto& cd = decoupled.irk->counters();
  std::printf(
      "  estimates agree to %.2e relative; factorisations coupled %ld (stage + "
      "filter), decoupled %ld\n",
      worst, cc.factorizations, cd.factorizations);
  EXPECT_LT(worst, 1e-8);
  EXPECT_LT(cd.factorizations, cc.factorizations);
  EXPECT_EQ(cd.linear_solves, cc.linear_solves);
}

TEST(DecoupledSelection, AutoDecouplesWhereExact) {
  catena::test::ensure_petsc();
  const model::Model m = pendulum(false);
  catena::assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
  auto make = [&](TableauFamily family, int stages, bool full_newton) {
    solvers::IrkOptions o;
    o.family = family;
    o.stages = stages;
    o.full_newton = full_newton;
    return solvers::IrkIntegrator(system, o).decoupled();
  };
  EXPECT_TRUE(make(TableauFamily::radau_iia, 3, false));
  EXPECT_TRUE(make(TableauFamily::gauss, 1, false));
  EXPECT_TRUE(make(TableauFamily::lobatto_iiic, 2, false));
  EXPECT_FALSE(make(TableauFamily::lobatto_iiia, 3, false));
  EXPECT_FALSE(make(TableauFamily::sdirk, 3, false));
  EXPECT_FALSE(make(TableauFamily::radau_iia, 3, true));
}

TEST(DecoupledSelection, DecoupledWhereNotExactIsAnInputError) {
  catena::test::ensure_petsc();
  const model::Model m = pendulum(false);
  catena::assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
  auto expect_refused = [&](TableauFamily family, int stages, bool full_newton,
                            const std::string& why) {
    solvers::IrkOptions o;
    o.family = family;
    o.stages = stages;
    o.full_newton = full_newton;
    o.linear_algebra = solvers::StageLinearAlgebra::decoupled;
    try {
      solvers::IrkIntegrator irk(system, o);
      ADD_FAILURE() << "accepted " << label({family, stages});
    } catch (const catena::InputError& e) {
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("linear_algebra"), std::string::npos) << e.what();
    }
  };
  expect_refused(TableauFamily::lobatto_iiia, 3, false, "singular");
  expect_refused(TableauFamily::sdirk, 3, false, "repeated eigenvalue");
  expect_refused(TableauFamily::radau_iia, 3, true, "full Newton");
}

}  // namespace
