// The modal model's stepping (solvers/modal/) against closed forms:
//  - exact_step: an undamped oscillator under a constant load from rest,
//    u = g/ω² (1 − cos ωh), u̇ = g/ω sin ωh; a damped one's free vibration,
//    u = e^{−ζωt} (cos ω_d t + ζω/ω_d sin ω_d t); a ramp load g = a t,
//    u = a/ω² (t − sin(ωt)/ω); and for a 2-DOF damped system one step of 2h equals two of h
//    (the step is the exact flow, a semigroup). Tolerances: 1e-12 relative (the matrix
//    exponential's round-off, scaled time keeping the load terms' digits);
//  - ModalStepper: a mode vibrating freely for 10 000 steps keeps its phase and amplitude
//    (no period error: cos ωt to 1e-9); a pantograph (one mass on a spring, pushed up)
//    under a one-mode wire settles at the closed-form contact force
//    F = k_c (F0/k_p) / (1 + k_c/k_p + k_c/ω² + k_c r) (r: the static correction's residual
//    flexibility, 0 and 1e-5 m/N); pulled down it loses contact (F = 0); a dropper pushed
//    below its slack point settles where the linear structure without the dropper puts it,
//    the tension it does not carry (its slack) the closed form's; a dropper slack at rest
//    (not in the mode) pulled taut carries the closed form's tension; and on a model with
//    every kind of site at once (12 modes, a two-DOF pantograph over three path elements,
//    three droppers, a full static correction), every step's end state puts each site
//    force on its law, evaluated from the model's data (not the stepper's bookkeeping).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <numbers>

#include "catena/elements/hermite.hpp"
#include "catena/solvers/modal/exact_step.hpp"
#include "catena/solvers/modal/modal_stepper.hpp"

namespace cs = catena::solvers;
using Eigen::MatrixXd;

namespace {

MatrixXd scalar(double x) { return MatrixXd::Constant(1, 1, x); }

TEST(ExactStep, UndampedOscillatorUnderAConstantLoad) {
  const double w = 2 * std::numbers::pi * 3.0, g = 2.0, h = 0.05;
  const cs::ExactStep s = cs::exact_step(scalar(w * w), scalar(0.0), h);
  const double u = (s.Gu0 + s.Gu1)(0, 0) * g, v = (s.Gv0 + s.Gv1)(0, 0) * g;
  EXPECT_NEAR(u, g / (w * w) * (1 - std::cos(w * h)), 1e-12 * g / (w * w));
  EXPECT_NEAR(v, g / w * std::sin(w * h), 1e-12 * g / w);
}

TEST(ExactStep, DampedFreeVibrationAndRampLoad) {
  const double w = 2 * std::numbers::pi * 40.0, zeta = 0.05, h = 1e-3;
  const cs::ExactStep s = cs::exact_step(scalar(w * w), scalar(2 * zeta * w), h);
  const double wd = w * std::sqrt(1 - zeta * zeta);
  const double u = std::exp(-zeta * w * h) * (std::cos(wd * h) + zeta * w / wd * std::sin(wd * h));
  EXPECT_NEAR(s.Euu(0, 0), u, 1e-12);
  // Ramp g = a t from rest, undamped, over one step: only Gu1 (g(0) = 0) acts.
  const double a = 3.0, T = 0.004;
  const cs::ExactStep r = cs::exact_step(scalar(w * w), scalar(0.0), T);
  EXPECT_NEAR(r.Gu1(0, 0) * a * T, a / (w * w) * (T - std::sin(w * T) / w), 1e-12 * a * T * T * T);
}

TEST(ExactStep, TwoHalfStepsAreOneStep) {
  MatrixXd K(2, 2), C(2, 2);
  K << 400.0, -150.0, -150.0, 2500.0;
  C << 0.8, -0.1, -0.1, 2.0;
  const double h = 0.01;
  const cs::ExactStep one = cs::exact_step(K, C, 2 * h), half = cs::exact_step(K, C, h);
  MatrixXd E(4, 4), Eh(4, 4);
  E << one.Euu, one.Euv, one.Evu, one.Evv;
  Eh << half.Euu, half.Euv, half.Evu, half.Evv;
  EXPECT_LT((E - Eh * Eh).cwiseAbs().maxCoeff(), 1e-12 * E.cwiseAbs().maxCoeff());
}

// A one-mode wire (ψ = 1 along a 10 m path, static height 0) under a one-mass pantograph
// (mass m, spring k_p to ground, load F0 up) with penalty stiffness k_c.
cs::ModalDynamics wire_and_pantograph(double w, double zeta, double F0, double r_self) {
  cs::ModalDynamics d;
  d.omega = {w};
  d.zeta = {zeta};
  d.constant_load = {0.0};
  d.Mp = scalar(10.0);
  d.Kp = scalar(5000.0);
  d.Cp = scalar(2 * 0.3 * std::sqrt(5000.0 * 10.0));
  d.f0p = Eigen::VectorXd::Constant(1, -F0);  // R = M a + K u + f0: f0 = −F0 pushes up
  cs::ModalContact c;
  c.name = "test";
  c.stations.start = {0.0, 10.0};
  c.node_a = {0};
  c.node_b = {1};
  c.rows = {1.0, 0.0, 1.0, 0.0};  // per node: ψ of r, then of r_x
  c.reference = {0.0, 0.0, 0.0, 0.0};
  c.stiffness = 50000.0;
  c.speed = 2.0;
  c.head = Eigen::VectorXd::Constant(1, 1.0);
  if (r_self > 0.0) {
    d.static_correction = true;
    // R over (r_A, r_A,x, r_B, r_B,x): r on the positions only, so Sᵀ R S = r (S1 + S3)² = r.
    c.residual = {r_self, 0, r_self, 0, 0, 0, 0, 0, r_self, 0, r_self, 0, 0, 0, 0, 0};
    c.residual_static = {0.0, 0.0, 0.0, 0.0};
    d.dropper_residual_static = Eigen::VectorXd::Zero(0);
  }
  d.contacts.push_back(c);
  return d;
}

TEST(ModalStepper, FreeModeKeepsItsPhase) {
  cs::ModalDynamics d;
  const double w = 2 * std::numbers::pi * 7.3, h = 5e-4;
  d.omega = {w};
  d.zeta = {0.0};
  d.constant_load = {0.0};
  d.f0p.resize(0);
  cs::ModalStepper stepper(d);
  cs::ModalState s = stepper.rest(0.0), next;
  s.eta(0) = 1.0;
  for (int k = 0; k < 10000; ++k) {
    ASSERT_TRUE(stepper.step(s, h, next).converged);
    s = next;
  }
  EXPECT_NEAR(s.eta(0), std::cos(w * 10000 * h), 1e-9);
  EXPECT_NEAR(s.eta_dot(0), -w * std::sin(w * 10000 * h), 1e-9 * w);
}

void settles_at_closed_form(double r_self) {
  const double w = 2 * std::numbers::pi * 4.0, F0 = 120.0;
  cs::ModalStepper stepper(wire_and_pantograph(w, 0.3, F0, r_self));
  cs::ModalState s = stepper.rest(0.0), next;
  for (int k = 0; k < 8000; ++k) {  // 4 s, within the 10 m path at 2 m/s
    ASSERT_TRUE(stepper.step(s, 5e-4, next).converged);
    s = next;
  }
  const double kc = 50000.0, kp = 5000.0;
  const double F = kc * (F0 / kp) / (1 + kc / kp + kc / (w * w) + kc * r_self);
  EXPECT_NEAR(s.contact_force[0], F, 1e-6 * F);
  EXPECT_NEAR(s.eta(0), F / (w * w), 1e-6 * F / (w * w));
  EXPECT_NEAR(stepper.penetration(s, 0), F / kc, 1e-6 * F / kc);
}

TEST(ModalStepper, PantographSettlesAtTheClosedFormContactForce) { settles_at_closed_form(0.0); }

TEST(ModalStepper, StaticCorrectionAddsItsFlexibility) { settles_at_closed_form(1e-5); }

TEST(ModalStepper, PulledDownPantographLosesContact) {
  cs::ModalStepper stepper(wire_and_pantograph(2 * std::numbers::pi * 4.0, 0.3, -50.0, 0.0));
  cs::ModalState s = stepper.rest(0.0), next;
  for (int k = 0; k < 4000; ++k) {
    ASSERT_TRUE(stepper.step(s, 5e-4, next).converged);
    s = next;
  }
  EXPECT_EQ(s.contact_force[0], 0.0);
  EXPECT_NEAR(stepper.penetration(s, 0), -50.0 / 5000.0, 1e-8);
}

TEST(ModalStepper, SlackDropperCarriesNoTension) {
  // One mode, ω² = 2000 s⁻² of which the dropper (elongation d = 1 per unit η, 1000 N/m,
  // 10 N at rest) gives 1000; a constant load −50 N pushes the mode down. Taut, the
  // linear answer would be η = −0.025 with tension 10 − 25 < 0: slack, the dropper's
  // stiffness and its 10 N go, 1000 η = −50 + 10, η = −0.04, and the tension the
  // dropper does not carry is −(10 + 1000 η) = 30 N.
  cs::ModalDynamics d;
  d.omega = {std::sqrt(2000.0)};
  d.zeta = {0.2};
  d.constant_load = {-50.0};
  d.f0p.resize(0);
  d.droppers.push_back({{1.0}, 10.0, 1000.0, 0.0});
  cs::ModalStepper stepper(d);
  cs::ModalState s = stepper.rest(0.0), next;
  for (int k = 0; k < 20000; ++k) {
    ASSERT_TRUE(stepper.step(s, 5e-4, next).converged);
    s = next;
  }
  EXPECT_NEAR(s.eta(0), -0.04, 1e-9);
  EXPECT_NEAR(s.slack[0], 30.0, 1e-6);
}

TEST(ModalStepper, DropperSlackAtRestTightensWhenPulled) {
  // The dropper slack at q0 (tension −10 N: 1 cm short of taut at 1000 N/m) is not in the
  // mode (ω² = 1000 s⁻² without it); a load of +50 N per unit modal mass pulls it taut:
  // 1000 η = 50 − (−10 + 1000 η) gives η = 0.03 and the tension it then adds,
  // −10 + 1000 η = 20 N.
  cs::ModalDynamics d;
  d.omega = {std::sqrt(1000.0)};
  d.zeta = {0.2};
  d.constant_load = {50.0};
  d.f0p.resize(0);
  d.droppers.push_back({{1.0}, -10.0, 1000.0, 0.0, false});
  cs::ModalStepper stepper(d);
  cs::ModalState s = stepper.rest(0.0), next;
  EXPECT_EQ(s.slack[0], 0.0);
  for (int k = 0; k < 20000; ++k) {
    ASSERT_TRUE(stepper.step(s, 5e-4, next).converged);
    s = next;
  }
  EXPECT_NEAR(s.eta(0), 0.03, 1e-9);
  EXPECT_NEAR(s.slack[0], 20.0, 1e-6);
}

}  // namespace

namespace site_laws {

// A model with every kind of site at once: 12 modes, a two-DOF pantograph whose contact runs
// over a three-element path, three droppers (one slack at rest), and a static correction
// drawn from one symmetric positive definite R over all the sites, so that its parts agree.
// Random but fixed (seeded) rows; the model is driven hard enough that the contact is lost
// and regained and droppers slacken.
struct Model {
  cs::ModalDynamics d;
  Eigen::MatrixXd R;  // over (path rows 0..7, droppers 8..10)
};

Model make_model() {
  std::srand(7);
  const auto uniform = [] { return 2.0 * std::rand() / RAND_MAX - 1.0; };
  Model m;
  cs::ModalDynamics& d = m.d;
  const int n = 12, nodes = 4, nd = 3, sites = 2 * nodes + nd;
  for (int i = 0; i < n; ++i) {
    d.omega.push_back(2 * std::numbers::pi * (1.5 + 4.0 * i + uniform()));
    d.zeta.push_back(0.01 + 0.005 * uniform());
    d.constant_load.push_back(20.0 * uniform());
  }
  d.Mp = (MatrixXd(2, 2) << 8.0, 0.0, 0.0, 7.0).finished();
  d.Kp = (MatrixXd(2, 2) << 3000.0, -3000.0, -3000.0, 3500.0).finished();
  d.Cp = (MatrixXd(2, 2) << 40.0, -40.0, -40.0, 60.0).finished();
  d.f0p = (Eigen::VectorXd(2) << 0.0, -140.0).finished();
  cs::ModalContact c;
  c.name = "test";
  c.stations.start = {0.0, 3.0, 7.0, 10.0};
  c.node_a = {0, 1, 2};
  c.node_b = {1, 2, 3};
  for (int r = 0; r < 2 * nodes * n; ++r) c.rows.push_back(0.05 * uniform());
  for (int r = 0; r < 2 * nodes; ++r) c.reference.push_back(0.01 * uniform());
  c.stiffness = 50000.0;
  c.damping = 5.0;
  c.speed = 2.0;
  c.start = 0.5;
  c.head = (Eigen::VectorXd(2) << 1.0, 0.0).finished();
  c.head_reference = 0.0;
  for (int j = 0; j < nd; ++j) {
    cs::ModalDropper dr;
    for (int i = 0; i < n; ++i) dr.elongation.push_back(0.02 * uniform());
    dr.stiffness = 2000.0;
    dr.damping = 2.0;
    dr.tension = j == 2 ? -2.0 : 5.0;
    dr.in_modes = j != 2;
    d.droppers.push_back(dr);
  }
  const MatrixXd B = MatrixXd::NullaryExpr(sites, sites, uniform);
  m.R = 1e-6 * (B.transpose() * B + 0.1 * MatrixXd::Identity(sites, sites));
  d.static_correction = true;
  for (int e = 0; e < 3; ++e) {
    const int row[4] = {2 * e, 2 * e + 1, 2 * e + 2, 2 * e + 3};
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) c.residual.push_back(m.R(row[a], row[b]));
  }
  for (int r = 0; r < 2 * nodes; ++r) {
    for (int j = 0; j < nd; ++j) c.residual_dropper.push_back(m.R(r, 2 * nodes + j));
    c.residual_static.push_back(1e-4 * uniform());
  }
  d.dropper_residual = m.R.bottomRightCorner(nd, nd);
  d.dropper_residual_static = Eigen::VectorXd::NullaryExpr(nd, [&] { return 1e-4 * uniform(); });
  d.contacts.push_back(c);
  return m;
}

TEST(ModalStepper, EveryStepEndsWithEverySiteOnItsLaw) {
  // Each step's end state, evaluated here from the model's own data (not the stepper's),
  // must put each site force on its law: F = max(0, k δ + c δ̇) while δ > 0 (else 0), and a
  // dropper's correction ΔT = ∓(T0 + k ε + c ε̇) while ∓(T0 + k ε) > 0 (else 0; the bar's
  // damping acts while its strain says taut, as in the element, so ΔT may be < 0), with
  // ε and δ including the static correction of every site force.
  const Model m = make_model();
  const cs::ModalDynamics& d = m.d;
  const cs::ModalContact& c = d.contacts[0];
  const int n = d.n_modes(), nd = 3;
  cs::ModalStepper stepper(d);
  cs::ModalState s = stepper.rest(0.0), next;
  s.eta(0) = 0.3;
  s.eta_dot(1) = -4.0;
  stepper.settle_forces(s);
  int lost = 0, touching = 0, slack = 0, tightened = 0;
  for (int k = 0; k < 8000; ++k) {  // 4 s: the contact crosses all three elements
    ASSERT_TRUE(stepper.step(s, 5e-4, next).converged) << "step " << k;
    s = next;
    const double x = c.position(s.t);
    if (!c.stations.contains(x)) break;
    const std::size_t e = c.stations.element_at(x);
    const auto h =
        catena::elements::hermite_at(x - c.stations.start[e], c.stations.element_length(e));
    Eigen::VectorXd psi = Eigen::VectorXd::Zero(n), dpsi = Eigen::VectorXd::Zero(n);
    Eigen::VectorXd site_weights = Eigen::VectorXd::Zero(8 + nd);  // R's rows at the point
    double w0 = 0.0, dw0 = 0.0;
    for (int b = 0; b < 4; ++b) {
      const int row = 2 * static_cast<int>(e) + b;  // nodes e, e + 1: rows 2e .. 2e + 3
      const Eigen::Map<const Eigen::VectorXd> r(c.rows.data() + row * n, n);
      psi += h.s[b] * r;
      dpsi += h.ds[b] * r;
      w0 += h.s[b] * c.reference[static_cast<std::size_t>(row)];
      dw0 += h.ds[b] * c.reference[static_cast<std::size_t>(row)];
      site_weights(row) = h.s[b];
    }
    // The static correction's forces: F at the point, −ΔT_j along each dropper.
    Eigen::VectorXd f = Eigen::VectorXd::Zero(8 + nd);
    f += s.contact_force[0] * site_weights;
    for (int j = 0; j < nd; ++j) f(8 + j) = -s.slack[static_cast<std::size_t>(j)];
    const Eigen::VectorXd u_r = m.R * f;
    double r_static = 0.0;
    for (int b = 0; b < 4; ++b)
      r_static += h.s[b] * c.residual_static[2 * e + static_cast<std::size_t>(b)];
    const double delta = c.head.dot(s.u) - (w0 + psi.dot(s.eta) + site_weights.dot(u_r) + r_static);
    const double rate =
        c.head.dot(s.u_dot) - psi.dot(s.eta_dot) - c.speed * (dw0 + dpsi.dot(s.eta));
    const double F = delta > 0.0 ? std::max(0.0, c.stiffness * delta + c.damping * rate) : 0.0;
    ASSERT_NEAR(s.contact_force[0], F, 1e-7 * (1.0 + F)) << "t = " << s.t;
    lost += F == 0.0;
    touching += F > 0.0;
    for (int j = 0; j < nd; ++j) {
      const cs::ModalDropper& dr = d.droppers[static_cast<std::size_t>(j)];
      const Eigen::Map<const Eigen::VectorXd> row(dr.elongation.data(), n);
      const double eps = row.dot(s.eta) + u_r(8 + j) + d.dropper_residual_static(j);
      const double elastic = dr.tension + dr.stiffness * eps, sign = dr.in_modes ? -1.0 : 1.0;
      const double law =
          sign * elastic > 0.0 ? sign * (elastic + dr.damping * row.dot(s.eta_dot)) : 0.0;
      ASSERT_NEAR(s.slack[static_cast<std::size_t>(j)], law, 1e-7 * (1.0 + law))
          << "dropper " << j << ", t = " << s.t;
      if (law > 0.0) (dr.in_modes ? slack : tightened) += 1;
    }
  }
  // The run went through every case (a law that was never active proves nothing).
  EXPECT_GT(lost, 0);
  EXPECT_GT(touching, 0);
  EXPECT_GT(slack, 0);
  EXPECT_GT(tightened, 0);
}

}  // namespace site_laws
