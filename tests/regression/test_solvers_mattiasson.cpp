// Mattiasson's large-deflection cantilever (IJNME 17 (1981) 145–153, Table 1) with the ANCF
// cable and the ANCF beam through the whole parallel pipeline (assembly, SNES, MUMPS).
// Tip deflection v/L, shortening u/L and rotation θ within 1e-4 of the table for
// P·L²/EI = 1, 3, 10. A near-inextensible section (EA·L²/EI = 1e8) makes the extensible
// elements converge to the elastica; the spatial convergence is printed. The table's
// 5-digit rounding (±5e-6) is the floor the errors reach.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <tuple>

#include "model_builders.hpp"
#include "petsc_test_session.hpp"
#include "static_solution.hpp"

using catena::Vec3;
namespace model = catena::model;

namespace {

struct Tip {
  double v, u, theta;
};

enum class Kind { cable, beam };

Tip cantilever_tip(Kind kind, double load_parameter, int n_elements) {
  const double L = 2.0, EI = 50.0, EA = 1e8 * EI / (L * L);
  model::Model m;
  m.gravity = Vec3::Zero();
  model::ElementProps props = model::CableProps{EA, EI, 1.0, 0.0, 0.0, {}, false, false};
  if (kind == Kind::beam) {
    model::BeamProps b;
    b.EA = EA;
    b.GA_y = b.GA_z = EA;  // Kirchhoff constraint weights
    b.GJ = EI;
    b.EI_y = b.EI_z = EI;
    b.mass_per_length = 1.0;
    props = b;
  }
  const auto nodes = catena::test::add_line(m, {0, 0, 0}, {L, 0, 0}, n_elements, props);
  catena::test::set_reference_frames(m);
  // Cable clamp: position and slope direction (rx_y, rx_z); the slope's length, i.e. the
  // axial strain at the root, stays free as in an extensible rod. Beam: all 12 DOFs.
  m.supports.push_back({nodes.front(), kind == Kind::cable ? 0x37u : 0xFFFu});
  m.nodal_loads.push_back({nodes.back(), Vec3(0, 0, -load_parameter * EI / (L * L))});
  m.static_options.initial_load_step = 0.1;
  const auto sol = catena::test::solve_static(MPI_COMM_WORLD, m);
  const int tip = nodes.back();
  const Vec3 x(sol.positions[3 * tip], sol.positions[3 * tip + 1], sol.positions[3 * tip + 2]);
  const Vec3 t(sol.slopes[3 * tip], sol.slopes[3 * tip + 1], sol.slopes[3 * tip + 2]);
  return {-x[2] / L, (L - x[0]) / L, std::atan2(-t[2], t[0])};
}

struct Reference {
  double load, v, u, theta;
};

}  // namespace

class Mattiasson : public ::testing::TestWithParam<std::tuple<Kind, Reference>> {};

TEST_P(Mattiasson, TipMatchesElastica) {
  catena::test::ensure_petsc();
  const auto [kind, ref] = GetParam();
  double previous = 0.0;
  for (int n : {4, 8, 16, 32}) {
    const Tip tip = cantilever_tip(kind, ref.load, n);
    const double error = std::max(
        {std::abs(tip.v - ref.v), std::abs(tip.u - ref.u), std::abs(tip.theta - ref.theta)});
    std::printf("  %s PL²/EI = %4.1f, %2d elements: v/L %.5f u/L %.5f θ %.5f (max error %.1e%s)\n",
                kind == Kind::cable ? "cable" : "beam ", ref.load, n, tip.v, tip.u, tip.theta,
                error, previous > 0 ? (", ratio " + std::to_string(previous / error)).c_str() : "");
    previous = error;
    if (n == 32) {
      EXPECT_NEAR(tip.v, ref.v, 1e-4);
      EXPECT_NEAR(tip.u, ref.u, 1e-4);
      EXPECT_NEAR(tip.theta, ref.theta, 1e-4);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    Table1, Mattiasson,
    ::testing::Combine(::testing::Values(Kind::cable, Kind::beam),
                       ::testing::Values(Reference{1.0, 0.30172, 0.05643, 0.46135},
                                         Reference{3.0, 0.60325, 0.25442, 0.98602},
                                         Reference{10.0, 0.81061, 0.55500, 1.43029})));
