// Pantographs and moving penalty contact (model::MovingContact), built from scene text:
//  - the contact's Jacobian (stiffness with the convective term of the moving point, and
//    damping) against central differences of the residual, in contact mid-element;
//  - the EN 50318 two-stage pantograph alone (its path ends before it starts: no
//    contact) vibrates at the analytic natural frequencies of its 2-DOF model when
//    started in each mode shape;
//  - on a taut wire the contact force starts at the static equilibrium's value, is never
//    negative, and drops to zero (loss of contact) and recovers when the head is thrown
//    down, without Newton failures.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "catena/assembly/petsc_call.hpp"
#include "catena/assembly/state_view.hpp"
#include "catena/model/scene_reader.hpp"
#include "catena/solvers/statics/static_solver.hpp"
#include "catena/solvers/time/hht_integrator.hpp"
#include "dynamics_fixtures.hpp"
#include "fd_jacobian.hpp"
#include "petsc_test_session.hpp"

namespace solvers = catena::solvers;
namespace model = catena::model;

namespace {

// A 20 m wire at 20 kN (pinned ends) with one pantograph; `extra` appends keys to it.
std::string wire_scene(const std::string& pantograph) {
  return R"(
sections:
  cw: {type: cable, EA: 1.8e7, EI: 195, mass_per_length: 1.35}
nodes:
  - {id: 1, position: [0, 0, 0]}
  - {id: 2, position: [20, 0, 0]}
lines:
  - {name: cw, from: 1, to: 2, elements: 40, section: cw, tension: 20000}
supports:
  - {node: 1, fix: pinned}
  - {node: 2, fix: pinned}
pantographs:
  - )" + pantograph +
         R"(
analysis: {type: dynamic, duration: 1.0}
)";
}

std::vector<double> dense(Mat A, PetscInt n) {
  std::vector<double> out(static_cast<size_t>(n * n));
  std::vector<PetscInt> all(static_cast<size_t>(n));
  for (PetscInt i = 0; i < n; ++i) all[static_cast<size_t>(i)] = i;
  CATENA_PETSC(MatGetValues(A, n, all.data(), n, all.data(), out.data()));
  return out;
}

void set_array(Vec x, const std::vector<double>& values) {
  PetscScalar* a = nullptr;
  CATENA_PETSC(VecGetArray(x, &a));
  for (size_t i = 0; i < values.size(); ++i) a[i] = values[i];
  CATENA_PETSC(VecRestoreArray(x, &a));
}

}  // namespace

TEST(PantographContact, JacobianMatchesFiniteDifferences) {
  catena::test::ensure_petsc();
  const model::Model m =
      model::parse_scene(wire_scene("{name: p, line: cw, speed: 40, start: 7.3, static_force: 120, "
                                    "model: en50318, contact: {stiffness: 50000, damping: 30}}"),
                         "pantograph.yaml");
  catena::assembly::SecondOrderSystem system(PETSC_COMM_SELF, m);
  catena::VecHandle q = system.create_vector(), v = system.create_vector(),
                    f = system.create_vector();
  system.reference_state(q.get());
  PetscInt n = 0;
  CATENA_PETSC(VecGetSize(q.get(), &n));
  // Head 2 cm into the wire, everything moving a little.
  std::vector<double> q0 = catena::test::owned_values(q.get()), v0(static_cast<size_t>(n));
  const int head = m.contacts[0].head_node;
  const PetscInt head_z = system.dof_map().global_dof(head, 2);
  q0[static_cast<size_t>(head_z)] += 0.02;
  for (PetscInt i = 0; i < n; ++i) {
    q0[static_cast<size_t>(i)] += 1e-3 * std::sin(0.7 * i);
    v0[static_cast<size_t>(i)] = 0.05 * std::cos(1.3 * i);
  }
  const double t = 0.011;  // s = 7.74 m: inside an element
  auto residual_q = [&](const std::vector<double>& x, std::vector<double>& out) {
    set_array(q.get(), x);
    set_array(v.get(), v0);
    system.force({q.get(), v.get(), {}, t}, f.get());
    out = catena::test::owned_values(f.get());
  };
  auto residual_v = [&](const std::vector<double>& x, std::vector<double>& out) {
    set_array(q.get(), q0);
    set_array(v.get(), x);
    system.force({q.get(), v.get(), {}, t}, f.get());
    out = catena::test::owned_values(f.get());
  };
  const auto K_fd = catena::test::central_difference_jacobian(residual_q, q0, static_cast<int>(n));
  const auto C_fd = catena::test::central_difference_jacobian(residual_v, v0, static_cast<int>(n));
  set_array(q.get(), q0);
  set_array(v.get(), v0);
  const auto states = catena::assembly::StateView(system).contact_states({q.get(), v.get(), {}, t});
  ASSERT_EQ(states.size(), 1u);
  EXPECT_GT(states[0].force, 500.0) << "the head must be in contact";
  catena::MatHandle K = system.create_matrix(), C = system.create_matrix();
  system.jacobian({q.get(), v.get(), {}, t}, {1.0, 0.0, 0.0}, K.get());
  system.jacobian({q.get(), v.get(), {}, t}, {0.0, 1.0, 0.0}, C.get());
  EXPECT_LT(catena::test::relative_max_difference(dense(K.get(), n), K_fd), 1e-6);
  EXPECT_LT(catena::test::relative_max_difference(dense(C.get(), n), C_fd), 1e-6);
}

TEST(PantographContact, FreePantographVibratesAtItsNaturalFrequencies) {
  catena::test::ensure_petsc();
  // Undamped EN 50318 stages, starting 5 m beyond the end of its path: no contact.
  const double m1 = 7.2, m2 = 15.0, k1 = 4200.0, k2 = 50.0;
  const model::Model m = model::parse_scene(
      wire_scene("{name: p, line: cw, speed: 10, start: 25, static_force: 1, "
                 "stages: [{mass: 7.2, stiffness: 4200}, {mass: 15.0, stiffness: 50}], "
                 "contact: {stiffness: 50000}}"),
      "pantograph.yaml");
  // det(K − ω² M) = 0 for K = [k1, −k1; −k1, k1 + k2], M = diag(m1, m2).
  const double a = m1 * m2, b = -(m1 * (k1 + k2) + m2 * k1), c = k1 * k2;
  const double disc = std::sqrt(b * b - 4 * a * c);
  const double w2[2] = {(-b - disc) / (2 * a), (-b + disc) / (2 * a)};
  const int head = m.contacts[0].head_node, frame = head + 1;
  for (double omega2 : w2) {
    // Mode shape: (k1 − ω² m1) x1 = k1 x2.
    const double x1 = 0.01, x2 = (k1 - omega2 * m1) * x1 / k1;
    catena::assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
    catena::VecHandle q = system.create_vector(), v = system.create_vector();
    system.reference_state(q.get());
    solvers::StaticSolver statics(system, m.static_options);
    statics.solve(q.get());  // the wire sags; the static force lifts the stages by F/k2
    const double offset = 0.0;
    const auto& dofs = system.dof_map();
    const double z_head =
        catena::test::global_value(MPI_COMM_WORLD, q.get(), dofs.global_dof(head, 2));
    const double z_frame =
        catena::test::global_value(MPI_COMM_WORLD, q.get(), dofs.global_dof(frame, 2));
    catena::test::set_global_value(q.get(), dofs.global_dof(head, 2), z_head + offset + x1);
    catena::test::set_global_value(q.get(), dofs.global_dof(frame, 2), z_frame + offset + x2);
    solvers::HhtOptions o;
    o.alpha = 0.0;
    solvers::HhtIntegrator hht(system, o);
    hht.set_state(0.0, q.get(), v.get(), nullptr);
    const double period = 2 * M_PI / std::sqrt(omega2);
    const int per_period = 400;
    const double dt = period / per_period;
    // Upward zero crossings of the head's deviation over ~3 periods: their spacing.
    double previous = x1, first_crossing = -1.0, last_crossing = -1.0;
    int crossings = 0;
    for (int step = 1; step <= 3 * per_period + 50; ++step) {
      catena::test::advance_fixed(hht, dt, 1);
      const double z =
          catena::test::global_value(MPI_COMM_WORLD, hht.q(), dofs.global_dof(head, 2)) - z_head -
          offset;
      if (previous < 0.0 && z >= 0.0) {
        const double tc = (step - 1 + previous / (previous - z)) * dt;
        if (crossings == 0) first_crossing = tc;
        last_crossing = tc;
        ++crossings;
      }
      previous = z;
    }
    ASSERT_GE(crossings, 3);
    const double measured = (last_crossing - first_crossing) / (crossings - 1);
    std::printf("mode f = %.4f Hz: measured period %.6f s, analytic %.6f s\n",
                std::sqrt(omega2) / (2 * M_PI), measured, period);
    // The trapezoidal rule's period error at 400 steps per period: (π/400)²/12 ≈ 5e-6.
    EXPECT_NEAR(measured / period, 1.0, 1e-4);
  }
}

TEST(PantographContact, LosesContactAndRecovers) {
  catena::test::ensure_petsc();
  const model::Model m = model::parse_scene(
      wire_scene("{name: p, line: cw, speed: 20, start: 4, static_force: 120, model: en50318}"),
      "pantograph.yaml");
  catena::assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
  catena::VecHandle q = system.create_vector(), v = system.create_vector();
  system.reference_state(q.get());
  solvers::StaticSolver statics(system, m.static_options);
  statics.solve(q.get());
  const double F0 =
      catena::assembly::StateView(system).contact_states({q.get(), nullptr, {}, 0.0})[0].force;
  // Static contact force: 120 N plus the frame spring's share of the wire's sag there.
  EXPECT_NEAR(F0, 120.0, 3.0);
  // Throw the head down at 1 m/s: it leaves the wire, and the uplift brings it back.
  const int head = m.contacts[0].head_node;
  catena::test::set_global_value(v.get(), system.dof_map().global_dof(head, 2), -1.0);
  solvers::HhtIntegrator hht(system, solvers::HhtOptions{});
  hht.set_state(0.0, q.get(), v.get(), nullptr);
  int free_steps = 0, contact_after_free = 0;
  double smallest = 1e300;
  for (int step = 0; step < 1500; ++step) {
    catena::test::advance_fixed(hht, 2e-4, 1);  // throws on Newton failure
    const double F = catena::assembly::StateView(system)
                         .contact_states({hht.q(), hht.v(), {}, hht.time()})[0]
                         .force;
    ASSERT_TRUE(std::isfinite(F));
    smallest = std::min(smallest, F);
    if (F == 0.0)
      ++free_steps;
    else if (free_steps > 0)
      ++contact_after_free;
  }
  EXPECT_GE(smallest, 0.0);
  EXPECT_GT(free_steps, 10) << "the head should have left the wire";
  EXPECT_GT(contact_after_free, 10) << "and come back into contact";
}
