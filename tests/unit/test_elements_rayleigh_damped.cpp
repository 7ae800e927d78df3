// Rayleigh damping on a kernel: D = α M + β K_ref with K_ref the inner element's tangent in
// the reference state, the force D v and C = D + the inner element's C, checked against the
// inner element and finite differences. (Modal damping ratio: regression test
// test_solvers_rayleigh_damping.)
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <random>
#include <span>

#include "catena/elements/ancf_cable.hpp"
#include "catena/elements/rayleigh_damped.hpp"
#include "element_checks.hpp"

using catena::Vec3;
namespace el = catena::elements;

namespace {

constexpr double kLength = 0.5;
const el::CableSection kWire{1.8e7, 195.0, 1.35, 1e-3, 20000.0 / 1.8e7};

// A straight cable along x: r_A = 0, r_B = (L, 0, 0), unit slopes.
std::vector<double> straight() { return {0, 0, 0, 1, 0, 0, kLength, 0, 0, 1, 0, 0}; }

std::unique_ptr<el::Element> cable() {
  return std::make_unique<el::AncfCable>(kLength, kWire, Vec3(0, 0, -9.81), Vec3::Zero());
}

}  // namespace

TEST(RayleighDamped, DampingMatrixIsMassPlusReferenceStiffness) {
  const el::RayleighCoefficients c{0.06, 7.6e-5};
  const std::vector<double> q_ref = straight();
  const el::RayleighDamped damped(cable(), c, q_ref);
  const auto inner = cable();
  std::vector<double> M(144), K(144), f(12);
  inner->mass(M.data());
  inner->evaluate({q_ref, {}, {}}, {true, true, false}, {f.data(), K.data(), nullptr});
  const std::span<const double> D = damped.damping_matrix();
  for (int k = 0; k < 144; ++k) EXPECT_NEAR(D[k], c.mass * M[k] + c.stiffness * K[k], 1e-9);
  // The tension's geometric stiffness is in K_ref: transverse rows are not zero (a
  // Kelvin–Voigt axial damper would leave them so).
  EXPECT_GT(std::abs(D[2 * 12 + 2] - c.mass * M[2 * 12 + 2]), 1e-3);
}

TEST(RayleighDamped, ForceAddsDvAndJacobiansMatchFiniteDifferences) {
  const el::RayleighCoefficients c{0.06, 7.6e-5};
  const el::RayleighDamped damped(cable(), c, straight());
  const auto inner = cable();
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  for (int trial = 0; trial < 4; ++trial) {
    std::vector<double> q = straight(), v(12);
    for (double& x : q) x += u(rng);
    for (double& x : v) x = 20 * u(rng);
    const std::vector<double> f = catena::test::element_force(damped, q, v, {});
    const std::vector<double> f_inner = catena::test::element_force(*inner, q, v, {});
    const std::span<const double> D = damped.damping_matrix();
    for (int i = 0; i < 12; ++i) {
      double Dv = 0.0;
      for (int j = 0; j < 12; ++j) Dv += D[i * 12 + j] * v[j];
      EXPECT_NEAR(f[i], f_inner[i] + Dv, 1e-9 * (1.0 + std::abs(f[i])));
    }
    const auto check = catena::test::check_element_jacobians(damped, q, v, {});
    EXPECT_LT(check.stiffness, 1e-5);
    EXPECT_LT(check.damping, 1e-6);
  }
}

TEST(RayleighDamped, NoVelocityNoDampingForce) {
  const el::RayleighDamped damped(cable(), {0.5, 1e-3}, straight());
  const auto inner = cable();
  const std::vector<double> q = straight();
  EXPECT_EQ(catena::test::element_force(damped, q, {}, {}),
            catena::test::element_force(*inner, q, {}, {}));
}

// The arena the element list keeps its damping matrices in (matrix_arena.hpp): blocks in
// the order asked for, each on a cache line, zeroed, and never moved by later blocks.
TEST(MatrixArena, BlocksFollowEachOtherOnCacheLinesAndStay) {
  el::MatrixArena arena(1024);
  double* first = arena.allocate(144);
  first[0] = 1.0;
  first[143] = 2.0;
  double* second = arena.allocate(144);
  EXPECT_EQ(second, first + 144);  // 144 doubles are 18 whole cache lines: no gap
  double* odd = arena.allocate(5);
  EXPECT_EQ(odd, second + 144);
  double* after_odd = arena.allocate(3);
  EXPECT_EQ(after_odd, odd + 8);  // 5 doubles take one whole line
  for (double* p : {first, second, odd, after_odd})
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(p) % 64, 0u);
  for (int k = 0; k < 144; ++k) EXPECT_EQ(second[k], 0.0);
  EXPECT_EQ(arena.chunks(), 1u);
  double* next_chunk = arena.allocate(1000);  // does not fit in the 1024 left: a new chunk
  EXPECT_EQ(arena.chunks(), 2u);
  double* large = arena.allocate(5000);  // larger than a chunk: a chunk of its own
  EXPECT_EQ(arena.chunks(), 3u);
  large[4999] = 3.0;
  next_chunk[999] = 4.0;
  EXPECT_EQ(first[0], 1.0);  // earlier blocks untouched by the later ones
  EXPECT_EQ(first[143], 2.0);
}

TEST(RayleighDamped, DampingMatrixInAnArenaIsTheElementsOwn) {
  const el::RayleighCoefficients c{0.06, 7.6e-5};
  const auto arena = std::make_shared<el::MatrixArena>();
  const el::RayleighDamped own(cable(), c, straight());
  const el::RayleighDamped a(cable(), c, straight(), arena), b(cable(), c, straight(), arena);
  const std::span<const double> D = own.damping_matrix(), Da = a.damping_matrix(),
                                Db = b.damping_matrix();
  ASSERT_EQ(Da.size(), 144u);
  EXPECT_EQ(Db.data(), Da.data() + 144);  // the list's matrices one after the other
  for (int k = 0; k < 144; ++k) {
    EXPECT_EQ(Da[k], D[k]);
    EXPECT_EQ(Db[k], D[k]);
  }
  std::vector<double> v(12);
  for (int k = 0; k < 12; ++k) v[k] = 0.1 * (k + 1);
  EXPECT_EQ(catena::test::element_force(a, straight(), v, {}),
            catena::test::element_force(own, straight(), v, {}));
}
