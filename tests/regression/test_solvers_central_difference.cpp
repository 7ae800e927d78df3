// Central differences (HhtIntegrator with HhtOptions::central_difference: Newmark β = 0,
// γ = ½) through the whole system (assembly, SNES, the direct solve) on a point mass on an
// elastic support, against closed forms:
// - undamped, its positions are those of the Störmer recursion
//   x_{n+1} − 2 x_n + x_{n−1} = −(ωh)² x_n with x_1 = x_0 (1 − (ωh)²/2) (from v_0 = 0):
//   x_n = x_0 cos(nθ), cos θ = 1 − (ωh)²/2, to round-off, for ωh < 2;
// - for ωh > 2 the recursion's root −cos θ ± sqrt(cos²θ − 1) exceeds 1 in magnitude and the
//   run grows (conditional stability, the limit ωh = 2);
// - with a dashpot (the implicit part: v₁ in the force), second order against the exact
//   damped oscillation, one Newton iteration per step (the matrix M + ½hC is exact);
// - the stability limit's ω_max against the dense spectrum of K x = ω² M x.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "catena/assembly/second_order_system.hpp"
#include "catena/core/error.hpp"
#include "catena/solvers/modes/modal_analysis.hpp"
#include "catena/solvers/time/hht_integrator.hpp"
#include "dynamics_fixtures.hpp"
#include "petsc_test_session.hpp"

using catena::Vec3;
namespace model = catena::model;

namespace {

constexpr double kMass = 2.0;
constexpr double kOmega = 2.0 * std::numbers::pi;  // undamped, period 1 s
constexpr double kX0 = 0.1;                        // m, initial displacement, at rest

struct Trajectory {
  std::vector<double> x;
  long newton_iterations = 0;
};

// n steps of h from (x0, 0); zeta: the dashpot's damping ratio (0: none).
Trajectory simulate(double h, int n, double zeta = 0.0) {
  model::Model m = catena::test::oscillator(kMass, kOmega);
  const double c = 2.0 * zeta * kMass * kOmega;
  m.elastic_supports.front().damping = Vec3(c, c, c);
  catena::assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
  catena::VecHandle q = system.create_vector(), v = system.create_vector();
  system.reference_state(q.get());
  const PetscInt g = system.dof_map().global_dof(0, 0);
  catena::test::set_global_value(q.get(), g, kX0);
  catena::solvers::HhtOptions options;
  options.central_difference = true;
  options.atol = 1e-12;
  catena::solvers::HhtIntegrator cd(system, options);
  EXPECT_EQ(cd.name(), "central_difference");
  cd.set_state(0.0, q.get(), v.get(), nullptr);
  Trajectory run;
  run.x.push_back(catena::test::global_value(system.comm(), cd.q(), g));
  for (int i = 0; i < n; ++i) {
    catena::test::advance_fixed(cd, h, 1);
    run.x.push_back(catena::test::global_value(system.comm(), cd.q(), g));
  }
  run.newton_iterations = cd.counters().newton_iterations;
  return run;
}

double damped_exact(double t, double zeta) {
  const double wd = kOmega * std::sqrt(1.0 - zeta * zeta);
  return kX0 * std::exp(-zeta * kOmega * t) *
         (std::cos(wd * t) + zeta / std::sqrt(1.0 - zeta * zeta) * std::sin(wd * t));
}

}  // namespace

TEST(CentralDifference, StormerRecursionToRoundOff) {
  catena::test::ensure_petsc();
  for (double wh : {0.3, 1.0, 1.99}) {
    const double h = wh / kOmega;
    const Trajectory run = simulate(h, 200);
    const double theta = std::acos(1.0 - 0.5 * wh * wh);
    double worst = 0.0;
    for (std::size_t n = 0; n < run.x.size(); ++n)
      worst = std::max(worst, std::abs(run.x[n] - kX0 * std::cos(static_cast<double>(n) * theta)));
    std::printf("omega h = %.2f: largest distance from x0 cos(n theta) %.2e m\n", wh, worst);
    EXPECT_LT(worst, 1e-9 * kX0) << "omega h = " << wh;
  }
}

TEST(CentralDifference, GrowsBeyondTheStabilityLimit) {
  catena::test::ensure_petsc();
  const double wh = 2.05;  // the recursion's larger root: 1 − (ωh)²/2 − sqrt(...) = −1.56
  const Trajectory run = simulate(wh / kOmega, 40);
  const double c = 1.0 - 0.5 * wh * wh;
  const double root = std::abs(c - std::sqrt(c * c - 1.0));
  EXPECT_GT(std::abs(run.x.back()), 1e6 * kX0);
  // The growth per step tends to the root's magnitude.
  EXPECT_NEAR(std::abs(run.x[40] / run.x[39]), root, 1e-3 * root);
}

TEST(CentralDifference, SecondOrderWithADashpot) {
  catena::test::ensure_petsc();
  const double zeta = 0.05;
  std::vector<double> errors;
  for (int n : {40, 80, 160}) {
    const Trajectory run = simulate(1.0 / n, n, zeta);
    errors.push_back(std::abs(run.x.back() - damped_exact(1.0, zeta)));
    // M + ½hC is the exact derivative of the residual in a₁: one iteration per step.
    EXPECT_EQ(run.newton_iterations, n) << n;
  }
  for (std::size_t i = 1; i < errors.size(); ++i) {
    const double order = std::log2(errors[i - 1] / errors[i]);
    std::printf("dashpot, zeta %.2f: observed order %.3f (errors %.3e -> %.3e m)\n", zeta, order,
                errors[i - 1], errors[i]);
    EXPECT_NEAR(order, 2.0, 0.1) << "errors " << errors[i - 1] << " -> " << errors[i];
  }
}

// The stability limit's ω_max (modes/modal_analysis.hpp, highest_frequency: Krylov–Schur on
// M⁻¹K) against the dense spectrum of K x = ω² M x: a taut string (its highest mode the
// cables' axial one, √105·c/L for their Lobatto-sampled strain), and the same string cut in
// two and joined by a spring of 100 EA/L, whose mode between the two cables' end nodes lies
// far above the cables' own.
TEST(CentralDifference, HighestFrequencyMatchesTheDenseSpectrum) {
  catena::test::ensure_petsc();
  for (const bool joint : {false, true}) {
    catena::test::TautString string;
    string.n = 12;
    model::Model m = string.model();
    if (joint) {
      // Split the line at its middle node: the right half's first element takes a new node
      // there, and a spring joins the two.
      const int middle = string.n / 2;
      const model::Node copy = m.nodes[static_cast<std::size_t>(middle)];
      m.nodes.push_back(copy);
      m.nodes.back().id = static_cast<std::int64_t>(m.nodes.size());
      const int twin = static_cast<int>(m.nodes.size()) - 1;
      for (model::ElementDesc& e : m.elements)
        if (e.nodes.front() == middle && e.nodes.back() == middle + 1) e.nodes.front() = twin;
      const double k = 100.0 * string.EA / (string.L / string.n);
      model::ElementDesc spring;
      spring.id = static_cast<std::int64_t>(m.elements.size()) + 1;
      spring.nodes = {middle, twin};
      spring.props = model::SpringProps{Vec3(k, k, k), Vec3::Zero()};
      m.elements.push_back(spring);
    }
    catena::assembly::SecondOrderSystem system(PETSC_COMM_SELF, m);
    catena::VecHandle q = system.create_vector();
    system.reference_state(q.get());
    catena::MatHandle K = system.create_matrix(), M = system.create_matrix();
    system.jacobian({q.get(), nullptr, {}}, {1.0, 0.0, 0.0}, K.get());
    system.jacobian({q.get(), nullptr, {}}, {0.0, 0.0, 1.0}, M.get());
    PetscInt size = 0;
    MatGetSize(K.get(), &size, nullptr);
    Eigen::MatrixXd k(size, size), mass(size, size);
    for (PetscInt i = 0; i < size; ++i)
      for (PetscInt j = 0; j < size; ++j) {
        MatGetValues(K.get(), 1, &i, 1, &j, &k(i, j));
        MatGetValues(M.get(), 1, &i, 1, &j, &mass(i, j));
      }
    const Eigen::MatrixXd k_sym = 0.5 * (k + k.transpose());
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(k_sym, mass,
                                                                  Eigen::EigenvaluesOnly);
    const double dense = std::sqrt(eig.eigenvalues().maxCoeff());
    const double omega = catena::solvers::highest_frequency(K.get(), M.get());
    const double c = std::sqrt(string.EA / string.mu), h = string.L / string.n;
    std::printf("%s: omega_max %.6g rad/s (dense %.6g; sqrt(105) c/L %.6g)\n",
                joint ? "with a spring joint" : "taut string", omega, dense,
                std::sqrt(105.0) * c / h);
    EXPECT_NEAR(omega, dense, 1e-6 * dense) << joint;
    if (joint) {
      EXPECT_GT(omega, 3.0 * std::sqrt(105.0) * c / h);
    } else {
      EXPECT_NEAR(omega, std::sqrt(105.0) * c / h, 2e-3 * omega);
    }
  }
}
