// Vibration modes (solvers/modes/modal_analysis.hpp) of a tensioned wire against the
// closed form of a tensioned Euler–Bernoulli beam with pinned ends,
//   f_n = n/(2L) √(T/μ) √(1 + n²π² EI/(T L²))
// (e.g. Graff, "Wave Motion in Elastic Solids", 1975, §4.2; T = 20 kN, μ = 1.35 kg/m,
// EI = 195 N·m², L = 60 m: f_1 = 1.014315 Hz, f_10 = 10.156558 Hz), on 1, 2 and 3 ranks:
//  - the ten lowest frequencies within 5e-6 relative of the closed form at 120 cubic
//    elements, the error growing as n⁴ with the mode number (3.4e-10 n⁴) and falling at
//    fourth order in the element length: mode 10 at 120 and 240 elements, 3.4e-6 and
//    2.7e-7, observed order 3.66, which is fourth order on top of a floor of 6e-8 (their
//    Richardson extrapolation; the closed form is the inextensible thin beam's);
//  - each shape, normalised to unit modal mass, is the sine n of the closed form;
//  - the eigenpairs' residuals are at the solver's tolerance;
//  - the same frequencies on every rank count (against MPI_COMM_SELF);
//  - the modes below a cut-off (compute_modes_below, spectrum slicing, the modal model's
//    solver): exactly the ten below 10.5 Hz (f_10 = 10.157, f_11 = 11.2 Hz; the first axial
//    mode is at 30 Hz), with the same frequencies, unit modal mass, and zero on DOFs left
//    out of `keep` (here the wire's first interior node's x: its modes then are those of a
//    wire whose node cannot move along it, which for bending modes changes nothing).
// The wire lies in the x–z plane (y and slope y held), so each bending mode appears once.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "catena/assembly/second_order_system.hpp"
#include "catena/assembly/state_view.hpp"
#include "catena/solvers/modes/modal_analysis.hpp"
#include "model_builders.hpp"
#include "petsc_test_session.hpp"

using catena::Vec3;
namespace model = catena::model;
namespace ct = catena::test;

namespace {

constexpr double kT = 20000.0, kMu = 1.35, kEI = 195.0, kL = 60.0, kEA = 1.8e7;
constexpr int kModes = 10;
constexpr unsigned kFixY = 1u << 1, kFixSlopeY = 1u << 4;

// The wire held at its ends with tension T: prestrain T/EA. Its mass per unstretched
// length μ(1 + ε) makes the mass per current length μ, and its bending energy per
// unstretched length ½EI κ₀² (κ₀ per unstretched length) is ½EI(1 + ε) κ² per current
// length: the closed form's EI is EI(1 + ε).
model::Model tensioned_wire(int n_elements) {
  model::Model m;
  model::CableProps props;
  const double strain = kT / kEA;
  props.EA = kEA;
  props.EI = kEI;
  props.mass_per_length = kMu * (1.0 + strain);
  props.prestrain = strain;
  const std::vector<int> nodes = ct::add_line(m, Vec3(0, 0, 0), Vec3(kL, 0, 0), n_elements, props);
  ct::set_reference_frames(m);
  for (const int node : nodes) m.supports.push_back({node, kFixY | kFixSlopeY});
  ct::pin(m, nodes.front());
  ct::pin(m, nodes.back());
  return m;
}

double closed_form(int n) {
  const double EI = kEI * (1.0 + kT / kEA);
  return n / (2.0 * kL) * std::sqrt(kT / kMu) *
         std::sqrt(1.0 + n * n * std::numbers::pi * std::numbers::pi * EI / (kT * kL * kL));
}

struct Result {
  std::vector<double> frequency, residual, shape_error;
};

Result modes_on(MPI_Comm comm, int n_elements = 120) {
  const model::Model m = tensioned_wire(n_elements);
  catena::assembly::SecondOrderSystem system(comm, m);
  catena::VecHandle q = system.create_vector();
  system.reference_state(q.get());  // straight under T: the equilibrium (no gravity)
  const catena::solvers::Modes modes = catena::solvers::compute_modes(system, q.get(), {kModes});
  Result r{modes.frequency, modes.residual, {}};
  // Shapes: the z displacement at the nodes against √(2/(μL)) sin(nπx/L), up to sign.
  for (int k = 0; k < kModes; ++k) {
    std::vector<double> positions, slopes;
    catena::assembly::StateView(system).owned_node_changes(modes.shape[k].get(), positions, slopes);
    const auto& owned = system.dof_map().owned_nodes();
    double dot = 0.0, error = 0.0;
    std::vector<double> z, expected;
    for (std::size_t i = 0; i < owned.size(); ++i) {
      const double x = m.nodes[owned[i]].position.x();
      z.push_back(positions[3 * i + 2]);
      expected.push_back(std::sqrt(2.0 / (kMu * kL)) *
                         std::sin((k + 1) * std::numbers::pi * x / kL));
      dot += z.back() * expected.back();
    }
    MPI_Allreduce(MPI_IN_PLACE, &dot, 1, MPI_DOUBLE, MPI_SUM, comm);
    const double sign = dot < 0.0 ? -1.0 : 1.0;
    for (std::size_t i = 0; i < z.size(); ++i)
      error = std::max(error, std::abs(sign * z[i] - expected[i]));
    MPI_Allreduce(MPI_IN_PLACE, &error, 1, MPI_DOUBLE, MPI_MAX, comm);
    r.shape_error.push_back(error / std::sqrt(2.0 / (kMu * kL)));
  }
  return r;
}

TEST(Modes, TensionedWireMatchesTheTensionedBeamClosedForm) {
  ct::ensure_petsc();
  const Result r = modes_on(MPI_COMM_WORLD);
  ASSERT_EQ(r.frequency.size(), static_cast<std::size_t>(kModes));
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  for (int k = 0; k < kModes; ++k) {
    const double exact = closed_form(k + 1);
    if (rank == 0)
      std::printf("  mode %2d: %.7f Hz (closed form %.7f, %.1e), residual %.1e, shape %.1e\n",
                  k + 1, r.frequency[k], exact, r.frequency[k] / exact - 1, r.residual[k],
                  r.shape_error[k]);
    EXPECT_NEAR(r.frequency[k] / exact, 1.0, 5e-6) << "mode " << k + 1;
    EXPECT_LT(r.residual[k], 1e-8);
    EXPECT_LT(r.shape_error[k], 1e-3);
  }
}

TEST(Modes, FrequencyErrorFallsAtFourthOrder) {
  ct::ensure_petsc();
  const double exact = closed_form(kModes);
  const double coarse = modes_on(MPI_COMM_WORLD, 120).frequency.back() / exact - 1.0;
  const double fine = modes_on(MPI_COMM_WORLD, 240).frequency.back() / exact - 1.0;
  const double order = std::log2(coarse / fine);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0)
    std::printf("  mode %d: error %.2e at 120 elements, %.2e at 240: order %.2f\n", kModes, coarse,
                fine, order);
  EXPECT_GT(order, 3.5);
  EXPECT_LT(order, 4.2);
}

TEST(Modes, SameFrequenciesOnEveryRankCount) {
  ct::ensure_petsc();
  const Result here = modes_on(MPI_COMM_WORLD);
  const Result alone = modes_on(MPI_COMM_SELF);
  for (int k = 0; k < kModes; ++k)
    EXPECT_NEAR(here.frequency[k], alone.frequency[k], 1e-10 * alone.frequency[k]);
}

TEST(Modes, ModesBelowACutOffAreAllOfThem) {
  ct::ensure_petsc();
  const model::Model m = tensioned_wire(120);
  catena::assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
  catena::VecHandle q = system.create_vector();
  system.reference_state(q.get());
  catena::MatHandle K = system.create_matrix(), M = system.create_matrix();
  const catena::assembly::EvalPoint at{q.get(), nullptr, {}, 0.0};
  system.jacobian(at, {1.0, 0.0, 0.0, 0.0, 0.0}, K.get());
  system.jacobian(at, {0.0, 0.0, 1.0, 0.0, 0.0}, M.get());
  const catena::assembly::DofMap& dofs = system.dof_map();
  const PetscInt left_out = dofs.global_dof(1, 0);  // node 1's x
  std::vector<PetscInt> keep;
  for (PetscInt g = dofs.first_owned(); g < dofs.first_owned() + dofs.n_owned(); ++g)
    if (g != left_out) keep.push_back(g);
  const catena::solvers::Modes modes =
      catena::solvers::compute_modes_below(K.get(), M.get(), keep, 10.5, q.get(), "test", "cutoff");
  ASSERT_EQ(modes.frequency.size(), static_cast<std::size_t>(kModes));
  for (int k = 0; k < kModes; ++k) {
    EXPECT_NEAR(modes.frequency[k] / closed_form(k + 1), 1.0, 5e-6) << "mode " << k + 1;
    EXPECT_LT(modes.residual[k], 1e-8);
    catena::VecHandle Mx = system.create_vector();
    MatMult(M.get(), modes.shape[k].get(), Mx.get());
    PetscScalar mass = 0.0;
    VecDot(Mx.get(), modes.shape[k].get(), &mass);
    EXPECT_NEAR(mass, 1.0, 1e-10);
    PetscInt first = 0, end = 0;
    VecGetOwnershipRange(modes.shape[k].get(), &first, &end);
    if (left_out >= first && left_out < end) {
      PetscScalar value = 1.0;
      VecGetValues(modes.shape[k].get(), 1, &left_out, &value);
      EXPECT_EQ(value, 0.0);
    }
  }
}

}  // namespace
