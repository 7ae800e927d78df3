// Local Newton corrections on 1, 2 and 3 ranks (assembly/local_patch.hpp,
// solvers/newton/local_newton.hpp).
//
// The patch evaluations must be exactly the whole system's where they claim to be: the
// force and the Newton matrix in the unknowns' rows, M d for d on the unknowns, and a
// change of the unknowns changes the force in the patch's rows only. LocalNewton must
// then bring a local disturbance of an HHT-type residual to the tolerance with r, q, v and
// f consistent with a fresh evaluation, and leave everything untouched when it cannot.
// Finally HHT with and without it on a moving load: the same solution (against full
// Newton as reference), with fewer residual evaluations.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <tuple>
#include <vector>

#include "catena/assembly/petsc_call.hpp"
#include "catena/assembly/second_order_system.hpp"
#include "catena/assembly/state_view.hpp"
#include "catena/core/mpi_comm.hpp"
#include "catena/model/scene_reader.hpp"
#include "catena/solvers/newton/local_newton.hpp"
#include "catena/solvers/statics/static_solver.hpp"
#include "catena/solvers/time/hht_integrator.hpp"
#include "dynamics_fixtures.hpp"
#include "global_vectors.hpp"
#include "model_builders.hpp"
#include "petsc_test_session.hpp"

using catena::Vec3;
namespace model = catena::model;
namespace assembly = catena::assembly;
namespace solvers = catena::solvers;

using catena::test::add_wave;
using catena::test::max_abs;

namespace {

constexpr int kElements = 240;  // 0.25 m elements on the 60 m line

// A 60 m, 20 kN contact wire with gravity, Kelvin–Voigt damping, point masses, an elastic
// support and a node pinned by a constraint (whose DOFs no patch may hold).
model::Model cable_line(int* constrained_node = nullptr) {
  model::Model m;
  m.gravity = Vec3(0, 0, -9.81);
  model::CableProps cw{1.8e7, 195.0, 1.35, 1e-3, 20000.0 / 1.8e7, {}};
  const auto nodes = catena::test::add_line(m, {0, 0, 0}, {60, 0, 0}, kElements, cw);
  for (int i = 8; i < kElements; i += 8) m.point_masses.push_back({nodes[i], 0.195});
  catena::test::set_reference_frames(m);
  catena::test::pin(m, nodes.front());
  catena::test::pin(m, nodes.back());
  m.elastic_supports.push_back({nodes[kElements / 3], Vec3(0, 300, 300), Vec3::Zero()});
  model::Constraint pinned;
  pinned.node_a = nodes[2 * kElements / 3];
  m.constraints.push_back(pinned);
  if (constrained_node) *constrained_node = pinned.node_a;
  return m;
}

// The patch around the middle of this rank's DOFs.
assembly::LocalPatch middle_patch(assembly::SecondOrderSystem& system, int layers) {
  const PetscInt n = system.dof_map().n_owned();
  return system.local_patch({n / 2}, layers);
}

}  // namespace

TEST(LocalPatch, EvaluatesWhatTheWholeSystemDoes) {
  catena::test::ensure_petsc();
  int constrained = -1;
  const model::Model m = cable_line(&constrained);
  assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
  system.prepare_local_patches();
  catena::VecHandle q = system.create_vector(), v = system.create_vector(),
                    f = system.create_vector();
  system.reference_state(q.get());
  add_wave(q.get(), 1e-3, 0.37, 0.0);
  add_wave(v.get(), 0.1, 0.21, 1.0);
  system.force({q.get(), v.get(), {}}, f.get());

  const assembly::LocalPatch patch = middle_patch(system, 4);
  ASSERT_FALSE(patch.empty());  // 80 elements per rank at most 3 ranks: an interior exists
  const std::vector<double> qa = catena::test::owned_values(q.get()),
                            va = catena::test::owned_values(v.get()),
                            fa = catena::test::owned_values(f.get());
  const double scale = *std::max_element(
      fa.begin(), fa.end(), [](double x, double y) { return std::abs(x) < std::abs(y); });

  // Force in the unknowns' rows.
  std::vector<double> f_rows(patch.rows.size());
  system.patch_force(patch, qa.data(), va.data(), f_rows.data());
  for (size_t i = 0; i < patch.rows.size(); ++i) {
    if (patch.unknown_of_row[i] < 0) continue;
    EXPECT_NEAR(f_rows[i], fa[patch.rows[i]], 1e-12 * std::abs(scale)) << "row " << patch.rows[i];
  }

  // M d for d on the unknowns, against the assembled mass matrix: equal in the rows, and
  // zero elsewhere.
  catena::MatHandle M = system.create_matrix();
  system.jacobian({q.get(), nullptr, {}}, {0.0, 0.0, 1.0}, M.get());
  catena::VecHandle d = system.create_vector(), Md = system.create_vector();
  std::vector<double> d_unknowns(patch.unknowns.size());
  for (size_t i = 0; i < d_unknowns.size(); ++i) {
    d_unknowns[i] = std::cos(0.3 * static_cast<double>(i)) + 0.5;
    CATENA_PETSC(VecSetValue(d.get(), system.dof_map().first_owned() + patch.unknowns[i],
                             d_unknowns[i], INSERT_VALUES));
  }
  CATENA_PETSC(VecAssemblyBegin(d.get()));
  CATENA_PETSC(VecAssemblyEnd(d.get()));
  CATENA_PETSC(MatMult(M.get(), d.get(), Md.get()));
  std::vector<double> Md_rows(patch.rows.size());
  system.patch_mass_product(patch, d_unknowns.data(), Md_rows.data());
  std::vector<double> Md_all = catena::test::owned_values(Md.get());
  const double Md_scale = max_abs(Md.get());
  for (size_t i = 0; i < patch.rows.size(); ++i) {
    EXPECT_NEAR(Md_rows[i], Md_all[patch.rows[i]], 1e-13 * Md_scale) << "row " << patch.rows[i];
    Md_all[patch.rows[i]] = 0.0;
  }
  for (double x : Md_all) EXPECT_EQ(x, 0.0);

  // The Newton matrix's block on the unknowns.
  const assembly::JacobianCoefficients c{3e-7, 6e-4, 1.0, 0.0, 0.0};
  catena::MatHandle J = system.create_matrix();
  system.jacobian({q.get(), v.get(), {}}, c, J.get());
  const size_t nu = patch.unknowns.size();
  std::vector<double> block(nu * nu, 0.0);
  for (const assembly::PatchEntry& e : system.patch_matrix(patch, qa.data(), va.data(), c))
    block[static_cast<size_t>(e.row) * nu + static_cast<size_t>(e.col)] += e.value;
  std::vector<PetscInt> global(nu);
  for (size_t i = 0; i < nu; ++i) global[i] = system.dof_map().first_owned() + patch.unknowns[i];
  std::vector<double> expected(nu * nu);
  CATENA_PETSC(MatGetValues(J.get(), static_cast<PetscInt>(nu), global.data(),
                            static_cast<PetscInt>(nu), global.data(), expected.data()));
  const double J_scale = *std::max_element(expected.begin(), expected.end());
  for (size_t i = 0; i < nu * nu; ++i) EXPECT_NEAR(block[i], expected[i], 1e-12 * J_scale);

  // No patch holds a constrained node's DOFs, even when seeded there.
  std::vector<PetscInt> all(static_cast<size_t>(system.dof_map().n_owned()));
  for (size_t i = 0; i < all.size(); ++i) all[i] = static_cast<PetscInt>(i);
  const assembly::LocalPatch everything = system.local_patch(all, 0);
  for (int k = 0; k < 3; ++k) {
    const PetscInt l = system.dof_map().local_dof(constrained, k);
    EXPECT_FALSE(std::binary_search(everything.unknowns.begin(), everything.unknowns.end(), l));
  }
}

TEST(LocalPatch, ChangingTheUnknownsChangesTheForceOnlyInTheRows) {
  catena::test::ensure_petsc();
  const model::Model m = cable_line();
  assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
  system.prepare_local_patches();
  catena::VecHandle q = system.create_vector(), v = system.create_vector(),
                    f0 = system.create_vector(), f1 = system.create_vector();
  system.reference_state(q.get());
  add_wave(q.get(), 1e-3, 0.37, 0.0);
  add_wave(v.get(), 0.1, 0.21, 1.0);
  const assembly::LocalPatch patch = middle_patch(system, 6);
  ASSERT_FALSE(patch.empty());

  std::vector<double> before(patch.rows.size()), after(patch.rows.size());
  system.force({q.get(), v.get(), {}}, f0.get());
  {
    const std::vector<double> qa = catena::test::owned_values(q.get()),
                              va = catena::test::owned_values(v.get());
    system.patch_force(patch, qa.data(), va.data(), before.data());
  }
  for (size_t i = 0; i < patch.unknowns.size(); ++i) {
    const PetscInt g = system.dof_map().first_owned() + patch.unknowns[i];
    CATENA_PETSC(
        VecSetValue(q.get(), g, 2e-3 * std::sin(1.3 * static_cast<double>(i)), ADD_VALUES));
    CATENA_PETSC(VecSetValue(v.get(), g, 0.2, ADD_VALUES));
  }
  for (Vec x : {q.get(), v.get()}) {
    CATENA_PETSC(VecAssemblyBegin(x));
    CATENA_PETSC(VecAssemblyEnd(x));
  }
  system.force({q.get(), v.get(), {}}, f1.get());
  {
    const std::vector<double> qa = catena::test::owned_values(q.get()),
                              va = catena::test::owned_values(v.get());
    system.patch_force(patch, qa.data(), va.data(), after.data());
  }
  std::vector<double> change = catena::test::owned_values(f1.get());
  const std::vector<double> old = catena::test::owned_values(f0.get());
  for (size_t i = 0; i < change.size(); ++i) change[i] -= old[i];
  double largest = 0.0;
  for (double x : change) largest = std::max(largest, std::abs(x));
  ASSERT_GT(largest, 1.0);  // the change is real (N)
  for (size_t i = 0; i < patch.rows.size(); ++i) {
    EXPECT_NEAR(change[patch.rows[i]], after[i] - before[i], 1e-9 * largest);
    change[patch.rows[i]] = 0.0;
  }
  for (double x : change) EXPECT_EQ(x, 0.0);  // elsewhere not even round-off
}

// A pantograph pressing on a 30 m wire (the scene of test_solvers_contact_ranks): a patch
// around the head holds the contact like a kernel, so its force and Newton-matrix block
// are the whole system's; where the contact's wire element lies on another rank, the
// contact's DOFs stay out of the patch.
TEST(LocalPatch, AContactCountsAsAKernel) {
  catena::test::ensure_petsc();
  const model::Model m =
      model::parse_scene(catena::test::pantograph_on_wire_scene(13.0), "contact.yaml");
  assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
  catena::VecHandle q = system.create_vector(), v = system.create_vector(),
                    f = system.create_vector();
  system.reference_state(q.get());
  solvers::StaticSolver(system, m.static_options).solve(q.get());
  add_wave(v.get(), 0.05, 0.21, 1.0);
  const double t = 0.01;
  ASSERT_GT(catena::assembly::StateView(system).contact_states({q.get(), v.get(), {}, t})[0].force,
            0.0);  // in contact
  system.prepare_local_patches();
  system.force({q.get(), v.get(), {}, t}, f.get());

  const int head = m.contacts[0].head_node;
  std::vector<PetscInt> seeds;
  const PetscInt n = system.dof_map().n_owned();
  for (int k = 0; k < 3; ++k)
    if (const PetscInt l = system.dof_map().local_dof(head, k); l >= 0 && l < n) seeds.push_back(l);
  const assembly::LocalPatch patch = system.local_patch(seeds, 8, t);
  int with_contact = patch.n_timed == 0 ? 0 : 1, any = 0;
  MPI_Allreduce(&with_contact, &any, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  if (catena::mpi_size(MPI_COMM_WORLD) == 1) {
    ASSERT_EQ(any, 1);
  }
  if (patch.n_timed == 0) {
    for (PetscInt l : seeds)  // the head is the contact's: fixed if the contact is out
      EXPECT_FALSE(std::binary_search(patch.unknowns.begin(), patch.unknowns.end(), l));
    return;
  }
  const std::vector<double> qa = catena::test::owned_values(q.get()),
                            va = catena::test::owned_values(v.get()),
                            fa = catena::test::owned_values(f.get());
  std::vector<double> f_rows(patch.rows.size());
  system.patch_force(patch, qa.data(), va.data(), f_rows.data());
  for (size_t i = 0; i < patch.rows.size(); ++i) {
    if (patch.unknown_of_row[i] < 0) continue;
    EXPECT_NEAR(f_rows[i], fa[patch.rows[i]], 1e-9) << "row " << patch.rows[i];
  }
  const assembly::JacobianCoefficients c{3e-7, 6e-4, 1.0, 0.0, 0.0};
  catena::MatHandle J = system.create_matrix();
  system.jacobian({q.get(), v.get(), {}, t}, c, J.get());
  const size_t nu = patch.unknowns.size();
  std::vector<double> block(nu * nu, 0.0), expected(nu * nu);
  for (const assembly::PatchEntry& e : system.patch_matrix(patch, qa.data(), va.data(), c))
    block[static_cast<size_t>(e.row) * nu + static_cast<size_t>(e.col)] += e.value;
  std::vector<PetscInt> global(nu);
  for (size_t i = 0; i < nu; ++i) global[i] = system.dof_map().first_owned() + patch.unknowns[i];
  CATENA_PETSC(MatGetValues(J.get(), static_cast<PetscInt>(nu), global.data(),
                            static_cast<PetscInt>(nu), global.data(), expected.data()));
  const double J_scale = *std::max_element(expected.begin(), expected.end());
  for (size_t i = 0; i < nu * nu; ++i) EXPECT_NEAR(block[i], expected[i], 1e-12 * J_scale);
}

namespace {

// The HHT-type residual R(a) = M a + c_f f(q̂ + c_q a, v̂ + c_v a) − c_f f(q̂, v̂), whose
// root is a = 0, with its states.
struct StepResidual {
  assembly::SecondOrderSystem& system;
  solvers::LocalNewton::Coefficients c;
  catena::MatHandle M;
  catena::VecHandle q_hat, v_hat, f_hat;

  StepResidual(assembly::SecondOrderSystem& s, const solvers::LocalNewton::Coefficients& coef)
      : system(s),
        c(coef),
        M(s.create_matrix()),
        q_hat(s.create_vector()),
        v_hat(s.create_vector()),
        f_hat(s.create_vector()) {
    system.reference_state(q_hat.get());
    add_wave(q_hat.get(), 1e-3, 0.37, 0.0);
    add_wave(v_hat.get(), 0.1, 0.21, 1.0);
    system.jacobian({q_hat.get(), nullptr, {}}, {0.0, 0.0, 1.0}, M.get());
    system.force({q_hat.get(), v_hat.get(), {}}, f_hat.get());
  }
  // q, v, f at a and r = R(a).
  void evaluate(Vec a, Vec q, Vec v, Vec f, Vec r) {
    CATENA_PETSC(VecWAXPY(q, c.c_q, a, q_hat.get()));
    CATENA_PETSC(VecWAXPY(v, c.c_v, a, v_hat.get()));
    system.force({q, v, {}}, f);
    CATENA_PETSC(MatMult(M.get(), a, r));
    CATENA_PETSC(VecAXPY(r, c.c_f, f));
    CATENA_PETSC(VecAXPY(r, -c.c_f, f_hat.get()));
  }
};

}  // namespace

TEST(LocalNewton, FinishesALocalDisturbanceExactly) {
  catena::test::ensure_petsc();
  const model::Model m = cable_line();
  assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
  const double h = 1e-3, alpha = -0.1, beta = 0.25 * (1 - alpha) * (1 - alpha), gamma = 0.5 - alpha;
  StepResidual R(system, {1 + alpha, beta * h * h, gamma * h});
  catena::VecHandle a = system.create_vector(), q = system.create_vector(),
                    v = system.create_vector(), f = system.create_vector(),
                    r = system.create_vector();
  // A bump of acceleration in the middle of each rank's DOFs.
  const PetscInt n = system.dof_map().n_owned(), lo = system.dof_map().first_owned();
  for (PetscInt i = n / 2 - 6; i <= n / 2 + 6; ++i)
    CATENA_PETSC(VecSetValue(a.get(), lo + i, 5.0, INSERT_VALUES));
  CATENA_PETSC(VecAssemblyBegin(a.get()));
  CATENA_PETSC(VecAssemblyEnd(a.get()));
  R.evaluate(a.get(), q.get(), v.get(), f.get(), r.get());
  const double start = max_abs(r.get());
  ASSERT_GT(start, 1.0);

  const double atol = 1e-3;  // N; the force's round-off here is about 1e-6 N per entry
  double norm = -1.0;
  // On this small line (1440 DOFs) a global iteration is cheaper than the windows: the
  // default cost cap (0.03·n unknowns) refuses them, and changes nothing.
  solvers::LocalNewtonSettings settings;
  settings.layers = 16;
  const std::vector<double> a_before = catena::test::owned_values(a.get()),
                            r_before = catena::test::owned_values(r.get());
  EXPECT_FALSE(solvers::LocalNewton(system, settings)
                   .correct(a.get(), r.get(), q.get(), v.get(), f.get(), R.c, atol, &norm));
  EXPECT_EQ(catena::test::owned_values(a.get()), a_before);
  EXPECT_EQ(catena::test::owned_values(r.get()), r_before);
  // Without the cap, the correction itself.
  settings.max_window_fraction = 1.0;
  solvers::LocalNewton local(system, settings);
  ASSERT_TRUE(local.correct(a.get(), r.get(), q.get(), v.get(), f.get(), R.c, atol, &norm));
  EXPECT_LE(norm, atol);
  EXPECT_EQ(local.counters().successes, 1);

  // r, q, v, f as a fresh evaluation at the corrected a gives them.
  catena::VecHandle q2 = system.create_vector(), v2 = system.create_vector(),
                    f2 = system.create_vector(), r2 = system.create_vector();
  R.evaluate(a.get(), q2.get(), v2.get(), f2.get(), r2.get());
  PetscReal fresh = 0.0;
  CATENA_PETSC(VecNorm(r2.get(), NORM_2, &fresh));
  EXPECT_LE(fresh, atol);
  EXPECT_NEAR(fresh, norm, 1e-5);
  const double f_scale = max_abs(f2.get());
  for (auto [mine, theirs, tolerance] : {std::tuple{r.get(), r2.get(), 1e-5},
                                         {q.get(), q2.get(), 1e-12},
                                         {v.get(), v2.get(), 1e-13},
                                         {f.get(), f2.get(), 1e-9 * f_scale}}) {
    CATENA_PETSC(VecAXPY(theirs, -1.0, mine));
    EXPECT_LE(max_abs(theirs), tolerance);
  }
  // The root is a = 0: the bump of 5 m/s² is gone (to the tolerance over the nodal mass).
  EXPECT_LT(max_abs(a.get()), 1e-2);
}

TEST(LocalNewton, LeavesASpreadResidualUntouched) {
  catena::test::ensure_petsc();
  const model::Model m = cable_line();
  assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
  StepResidual R(system, {0.9, 3e-7, 6e-4});
  catena::VecHandle a = system.create_vector(), q = system.create_vector(),
                    v = system.create_vector(), f = system.create_vector(),
                    r = system.create_vector();
  add_wave(a.get(), 1.0, 0.9, 0.3);  // everywhere
  R.evaluate(a.get(), q.get(), v.get(), f.get(), r.get());
  std::vector<std::vector<double>> before;
  for (Vec x : {a.get(), r.get(), q.get(), v.get(), f.get()})
    before.push_back(catena::test::owned_values(x));

  solvers::LocalNewtonSettings uncapped;  // so that the refusal is the spread's, not the cap's
  uncapped.max_window_fraction = 1.0;
  solvers::LocalNewton local(system, uncapped);
  double norm = -1.0;
  EXPECT_FALSE(local.correct(a.get(), r.get(), q.get(), v.get(), f.get(), R.c, 1e-3, &norm));
  int k = 0;
  for (Vec x : {a.get(), r.get(), q.get(), v.get(), f.get()})
    EXPECT_EQ(catena::test::owned_values(x), before[static_cast<size_t>(k++)]) << "vector " << k;
}

namespace {

// `steps` HHT steps of 1 ms from the straight, tensioned wire at rest.
struct MovingLoadRun {
  catena::VecHandle q;
  solvers::IntegratorCounters counters;
};

MovingLoadRun run_moving_load(assembly::SecondOrderSystem& system,
                              const solvers::HhtOptions& options, int steps) {
  solvers::HhtIntegrator hht(system, options);
  catena::VecHandle q = system.create_vector(), v = system.create_vector();
  system.reference_state(q.get());
  hht.set_state(0.0, q.get(), v.get(), nullptr);
  catena::test::advance_fixed(hht, 1e-3, steps);
  MovingLoadRun run{system.create_vector(), hht.counters()};
  CATENA_PETSC(VecCopy(hht.q(), run.q.get()));
  return run;
}

}  // namespace

// A 120 m, 20 kN wire (0.25 m elements, no gravity) under 120 N moving up at 80 m/s from
// x = 15 m: over 40 steps the load and its windows (±8 m) stay within the first third of
// the line, on one rank whether it runs on 1, 2 or 3 (a load at a partition boundary is
// finished by global iterations, which this test is not about).
TEST(LocalNewton, HhtOnAMovingLoadKeepsItsSolutionWithFewerResiduals) {
  catena::test::ensure_petsc();
  model::Model m;
  m.gravity = Vec3::Zero();
  model::CableProps cw{1.8e7, 195.0, 1.35, 0.0, 20000.0 / 1.8e7, {}};
  constexpr int kLineElements = 480;
  const auto nodes = catena::test::add_line(m, {0, 0, 0}, {120, 0, 0}, kLineElements, cw);
  catena::test::set_reference_frames(m);
  catena::test::pin(m, nodes.front());
  catena::test::pin(m, nodes.back());
  model::MovingLoad load;
  load.name = "pantograph";
  for (int e = 0; e < kLineElements; ++e) load.elements.push_back(e);
  load.force = Vec3(0, 0, 120);
  load.speed = 80.0;
  load.start = 15.0;
  m.moving_loads.push_back(load);
  assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);

  constexpr int kSteps = 40;
  solvers::HhtOptions off, full, on;
  off.local_newton = false;
  full.local_newton = false;
  full.full_newton = true;
  // On by default; uncapped, as this line (2880 DOFs) is too small for the windows to
  // be cheaper than a global iteration: the test is of the results, not the economy.
  ASSERT_TRUE(on.local_newton);
  on.local_newton_settings.max_window_fraction = 1.0;
  const MovingLoadRun with = run_moving_load(system, on, kSteps);
  const MovingLoadRun without = run_moving_load(system, off, kSteps);
  const MovingLoadRun reference = run_moving_load(system, full, kSteps);

  // The corrections end most solves, and save residual evaluations.
  EXPECT_GT(with.counters.local_corrections, kSteps / 2);
  // One global iteration per step instead of two (measured: 94 residuals against 188).
  EXPECT_LE(static_cast<double>(with.counters.residual_evaluations),
            0.6 * static_cast<double>(without.counters.residual_evaluations));
  EXPECT_EQ(without.counters.local_corrections, 0);
  // Both solve the same steps: against full Newton, the same distance (Newton tolerance).
  catena::VecHandle d = system.create_vector();
  CATENA_PETSC(VecWAXPY(d.get(), -1.0, reference.q.get(), with.q.get()));
  const double with_error = max_abs(d.get());
  CATENA_PETSC(VecWAXPY(d.get(), -1.0, reference.q.get(), without.q.get()));
  const double without_error = max_abs(d.get());
  catena::VecHandle rest = system.create_vector();
  system.reference_state(rest.get());
  CATENA_PETSC(VecWAXPY(d.get(), -1.0, rest.get(), reference.q.get()));
  const double motion = max_abs(d.get());
  // Both within reach of the Newton tolerance (measured at np 1, 2, 3: 1.5e-9 and 1.9e-9
  // of a 1.4e-2 motion); a wrong residual update would move the solution by orders more.
  EXPECT_LE(with_error, 5e-7 * motion);
  EXPECT_LE(without_error, 5e-7 * motion);
}
