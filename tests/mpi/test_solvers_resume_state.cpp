// The integrators' step-to-step state (solvers/resume_state.hpp) on 1, 2 and 3 ranks: an
// integrator set to a saved state (t, q, v, a) and given the saved resume state continues
// exactly as the integrator that saved it — every owned value of q, v, a bit for bit, and
// the same counters — for HHT with a moving contact and local Newton, and for Radau IIA
// with three stages (decoupled stage solve). Set to the state alone it does not (the
// reused tangent, HHT's f0 and the IRK predictor's stages are missing).
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "catena/assembly/petsc_call.hpp"
#include "catena/assembly/second_order_system.hpp"
#include "catena/assembly/state_view.hpp"
#include "catena/model/scene_reader.hpp"
#include "catena/solvers/statics/static_solver.hpp"
#include "catena/solvers/time/hht_integrator.hpp"
#include "catena/solvers/time/irk/irk_integrator.hpp"
#include "catena/solvers/time/multistep/adams_pece_integrator.hpp"
#include "catena/solvers/time/multistep/multistep_integrator.hpp"
#include "catena/solvers/time/rattle_integrator.hpp"
#include "dynamics_fixtures.hpp"
#include "lagrange_top.hpp"
#include "model_builders.hpp"
#include "petsc_test_session.hpp"

namespace model = catena::model;
namespace assembly = catena::assembly;
namespace solvers = catena::solvers;
using catena::test::owned_values;

namespace {

catena::VecHandle copy_of(Vec x) {
  catena::VecHandle y;
  CATENA_PETSC(VecDuplicate(x, y.out()));
  CATENA_PETSC(VecCopy(x, y.get()));
  return y;
}

// A saved integrator: its state and its resume state, with copies of the vectors (the
// integrator's own change as it goes on).
struct Saved {
  double t = 0.0;
  catena::VecHandle q, v, a;
  std::vector<catena::VecHandle> copies;
  solvers::ResumeState resume;

  explicit Saved(const solvers::TimeIntegrator& in)
      : t(in.time()), q(copy_of(in.q())), v(copy_of(in.v())), a(copy_of(in.a())) {
    in.save_resume_state(resume);
    for (auto& [name, vector] : resume.vectors) {
      copies.push_back(copy_of(vector));
      vector = copies.back().get();
    }
  }
};

struct Continued {
  std::vector<double> q, v, a;
  long newton_iterations = 0, factorizations = 0;
};

Continued continue_for(solvers::TimeIntegrator& in, double dt, int steps) {
  catena::test::advance_fixed(in, dt, steps);
  return {owned_values(in.q()), owned_values(in.v()), owned_values(in.a()),
          in.counters().newton_iterations, in.counters().factorizations};
}

// Runs `make()` for `before` steps, saves, runs on; a second integrator restored from the
// save, and a third set to the state alone, run the same steps.
template <class Make>
void expect_exact_continuation(Make make, Vec q0, Vec v0, double dt, int before, int after) {
  std::unique_ptr<solvers::TimeIntegrator> first = make();
  first->set_state(0.0, q0, v0, nullptr);
  catena::test::advance_fixed(*first, dt, before);
  const Saved saved(*first);
  const Continued reference = continue_for(*first, dt, after);

  std::unique_ptr<solvers::TimeIntegrator> restored = make();
  restored->set_state(saved.t, saved.q.get(), saved.v.get(), saved.a.get());
  restored->restore_resume_state(saved.resume);
  // An explicit method's stability limit is the uninterrupted run's, not one measured again
  // at the restart's state.
  EXPECT_EQ(restored->stable_step(), first->stable_step());
  const Continued resumed = continue_for(*restored, dt, after);
  EXPECT_EQ(resumed.q, reference.q);
  EXPECT_EQ(resumed.v, reference.v);
  EXPECT_EQ(resumed.a, reference.a);
  EXPECT_EQ(resumed.newton_iterations, reference.newton_iterations);
  // The restore rebuilds the Newton matrix at most once more than the saved run did.
  EXPECT_GE(resumed.factorizations, reference.factorizations);
  EXPECT_LE(resumed.factorizations, reference.factorizations + 1);

  std::unique_ptr<solvers::TimeIntegrator> fresh = make();
  fresh->set_state(saved.t, saved.q.get(), saved.v.get(), saved.a.get());
  const Continued afresh = continue_for(*fresh, dt, after);
  int differs = afresh.q != reference.q ? 1 : 0, any = 0;
  MPI_Allreduce(&differs, &any, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  EXPECT_EQ(any, 1) << "the state alone already continues exactly: the test shows nothing";
}

}  // namespace

TEST(ResumeState, HhtWithContactAndLocalNewtonContinuesBitForBit) {
  catena::test::ensure_petsc();
  const model::Model m =
      model::parse_scene(catena::test::pantograph_on_wire_scene(13.0), "contact.yaml");
  assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
  catena::VecHandle q = system.create_vector(), v = system.create_vector();
  system.reference_state(q.get());
  solvers::StaticSolver(system, m.static_options).solve(q.get());
  ASSERT_GT(
      catena::assembly::StateView(system).contact_states({q.get(), v.get(), {}, 0.0})[0].force,
      0.0);
  const solvers::HhtOptions options;  // local Newton on
  expect_exact_continuation(
      [&] { return std::make_unique<solvers::HhtIntegrator>(system, options); }, q.get(), v.get(),
      2e-4, 60, 60);
}

// Park's method keeps three points of history and its matrix's w₀: all of it travels.
TEST(ResumeState, ParkWithContactContinuesBitForBit) {
  catena::test::ensure_petsc();
  const model::Model m =
      model::parse_scene(catena::test::pantograph_on_wire_scene(13.0), "contact.yaml");
  assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
  catena::VecHandle q = system.create_vector(), v = system.create_vector();
  system.reference_state(q.get());
  solvers::StaticSolver(system, m.static_options).solve(q.get());
  solvers::MultistepOptions options;
  options.family = solvers::MultistepFamily::park;
  expect_exact_continuation(
      [&] { return std::make_unique<solvers::MultistepIntegrator>(system, options); }, q.get(),
      v.get(), 2e-4, 60, 60);
}

// BDF-3 saved in its start (two points of history of three), and Adams–Bashforth–Moulton,
// whose stability limit comes from the spectrum at the run's start, on the nonlinear
// plucked string (its stiffness, and so ω_max, changes as it swings).
TEST(ResumeState, BdfInItsStartAndAdamsContinueBitForBit) {
  catena::test::ensure_petsc();
  catena::test::TautString string;
  string.n = 12;
  const model::Model m = string.model();
  assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
  catena::VecHandle q = system.create_vector(), v = system.create_vector();
  system.reference_state(q.get());
  string.pluck(system, q.get(), 0.05);
  solvers::MultistepOptions bdf;
  bdf.order = 3;
  expect_exact_continuation(
      [&] { return std::make_unique<solvers::MultistepIntegrator>(system, bdf); }, q.get(), v.get(),
      0.01, 2, 10);
  solvers::AdamsPeceOptions adams;
  adams.order = 2;
  expect_exact_continuation(
      [&] { return std::make_unique<solvers::AdamsPeceIntegrator>(system, adams); }, q.get(),
      v.get(), 1e-4, 60, 60);
}

TEST(ResumeState, RadauContinuesBitForBit) {
  catena::test::ensure_petsc();
  const catena::test::TautString string;
  const model::Model m = string.model();
  assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
  catena::VecHandle q = system.create_vector(), v = system.create_vector();
  system.reference_state(q.get());
  string.pluck(system, q.get(), 0.05);
  solvers::IrkOptions options;
  options.family = solvers::TableauFamily::radau_iia;
  options.stages = 3;
  expect_exact_continuation(
      [&] { return std::make_unique<solvers::IrkIntegrator>(system, options); }, q.get(), v.get(),
      0.02, 10, 10);
}

// RATTLE on the heavy top (a rigid body's nonlinear frame constraints): the Newton
// matrix's point and h, and the stability limit of the run's start, travel.
TEST(ResumeState, RattleOnTheHeavyTopContinuesBitForBit) {
  catena::test::ensure_petsc();
  const catena::test::Top top;
  const model::Model m = model::parse_scene(top.scene(), "heavy_top.yaml");
  assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
  catena::VecHandle q = system.create_vector(), v = system.create_vector();
  system.reference_state(q.get());
  catena::test::set_top_velocity(system, top, v.get());
  expect_exact_continuation(
      [&] { return std::make_unique<solvers::RattleIntegrator>(system, solvers::RattleOptions{}); },
      q.get(), v.get(), 1e-3, 60, 60);
}
