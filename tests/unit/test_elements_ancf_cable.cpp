// ANCF cable kernel: exact Jacobians vs finite differences, rigid-motion invariance,
// closed-form mass matrix, axial and bending patch tests.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>

#include "catena/elements/ancf_cable.hpp"
#include "element_checks.hpp"

using catena::CurvatureMeasure;
using catena::Vec3;
using catena::elements::AncfCable;
using catena::elements::CableSection;

namespace {

const CableSection kSection{1.8e7, 195.0, 1.35, 0.02, 1.0e-3};
const Vec3 kGravity(0, 0, -9.81);

// Reference state of a straight element from a to b: [r_A, t, r_B, t].
std::vector<double> straight(const Vec3& a, const Vec3& b) {
  const Vec3 t = (b - a).normalized();
  return {a[0], a[1], a[2], t[0], t[1], t[2], b[0], b[1], b[2], t[0], t[1], t[2]};
}

std::vector<double> perturbed(std::vector<double> q, double amplitude, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-amplitude, amplitude);
  for (double& x : q) x += u(rng);
  return q;
}

// K and C against finite differences at `trials` random perturbations of q (amplitude
// `amplitude`) with random velocities of up to 1.
void expect_jacobians_match(const AncfCable& cable, const std::vector<double>& q, double amplitude,
                            unsigned seed, int trials) {
  std::mt19937 rng(seed);
  for (int trial = 0; trial < trials; ++trial) {
    const auto check = catena::test::check_element_jacobians(
        cable, perturbed(q, amplitude, rng), perturbed(std::vector<double>(12, 0.0), 1.0, rng),
        1.0);
    EXPECT_LT(check.stiffness, 1e-6) << "trial " << trial;
    EXPECT_LT(check.damping, 1e-6) << "trial " << trial;
  }
}

}  // namespace

TEST(AncfCable, JacobiansMatchFiniteDifferencesAtRandomStates) {
  for (const auto law : {CurvatureMeasure::reference_length, CurvatureMeasure::deformed_length}) {
    std::mt19937 rng(42);
    CableSection s = kSection;
    s.curvature = law;
    const AncfCable cable(2.0, s, kGravity, Vec3(0, 1.0, -3.0));
    for (int trial = 0; trial < 8; ++trial) {
      const auto q = perturbed(straight({0, 0, 0}, {2, 0, 0}), 0.2, rng);
      const auto v = perturbed(std::vector<double>(12, 0.0), 1.0, rng);
      const double lambda = std::uniform_real_distribution<double>(0.2, 1.0)(rng);
      const auto check = catena::test::check_element_jacobians(cable, q, v, lambda);
      EXPECT_LT(check.stiffness, 1e-6) << "trial " << trial << ", law " << static_cast<int>(law);
      EXPECT_LT(check.damping, 1e-6) << "trial " << trial << ", law " << static_cast<int>(law);
    }
  }
}

TEST(AncfCable, StiffnessIsSymmetricWithoutDamping) {
  std::mt19937 rng(7);
  CableSection s = kSection;
  s.damping_time = 0.0;
  const AncfCable cable(1.5, s, kGravity, Vec3::Zero());
  const auto q = perturbed(straight({0, 0, 0}, {1.5, 0, 0}), 0.1, rng);
  std::vector<double> f(12), K(144);
  cable.evaluate({q, {}, {}}, {true, true, false}, {f.data(), K.data(), nullptr});
  double asym = 0.0, scale = 0.0;
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j) {
      asym = std::max(asym, std::abs(K[i * 12 + j] - K[j * 12 + i]));
      scale = std::max(scale, std::abs(K[i * 12 + j]));
    }
  EXPECT_LT(asym / scale, 1e-12);
}

TEST(AncfCable, NoInternalForceUnderRigidMotion) {
  CableSection s = kSection;
  s.prestrain = 0.0;
  const AncfCable cable(3.0, s, Vec3::Zero(), Vec3::Zero());
  // Translate and rotate the stress-free reference configuration by a large rotation.
  const Eigen::AngleAxisd R(1.234, Vec3(0.3, -0.5, 0.8).normalized());
  const Vec3 shift(10.0, -4.0, 2.5);
  const Vec3 a = shift, b = shift + R * Vec3(3.0, 0, 0);
  const auto q = straight(a, b);
  // Rigid velocity: v = ω × (x − a) for positions, ω × t for slopes.
  const Vec3 omega(0.4, 1.1, -0.7), t = R * Vec3::UnitX();
  const Vec3 vb = omega.cross(b - a), vt = omega.cross(t);
  const std::vector<double> v = {0,     0,     0,     vt[0], vt[1], vt[2],
                                 vb[0], vb[1], vb[2], vt[0], vt[1], vt[2]};
  const auto f = catena::test::element_force(cable, q, v, 1.0);
  // Round-off floor: EA·1e-13 (|r'| = 1 to machine precision).
  for (double x : f) EXPECT_NEAR(x, 0.0, 1e-13 * s.EA);
}

TEST(AncfCable, MassMatrixMatchesClosedForm) {
  const double L = 2.5, mu = 1.35, eps_p = 2e-3;
  CableSection s = kSection;
  s.prestrain = eps_p;
  s.mass_per_length = mu;
  const AncfCable cable(L, s, kGravity, Vec3::Zero());
  std::vector<double> M(144);
  cable.mass(M.data());
  // Total mass from the translation block: Σ_ij M[x-dofs of positions]·(unit shift) = μ L0.
  // A unit translation is q = [e, 0, e, 0]; its kinetic "mass" eᵀ M e = total mass.
  std::vector<double> e(12, 0.0);
  e[0] = e[6] = 1.0;
  double total = 0.0;
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j) total += e[i] * M[i * 12 + j] * e[j];
  EXPECT_NEAR(total, mu * L / (1 + eps_p), 1e-12);
  // Entry (r_A,x ; r_A,x) = μ_x L/420 · 4 L².
  EXPECT_NEAR(M[3 * 12 + 3], mu / (1 + eps_p) * L / 420.0 * 4 * L * L, 1e-14);
  EXPECT_NEAR(M[0 * 12 + 9], mu / (1 + eps_p) * L / 420.0 * (-13 * L), 1e-14);
}

TEST(AncfCable, UniformStretchGivesAxialForceEAEpsilon) {
  CableSection s = kSection;
  s.damping_time = 0.0;
  const double L = 4.0, stretch = 1.01;
  const AncfCable cable(L, s, Vec3::Zero(), Vec3::Zero());
  // r(x) = stretch·x e_x: slopes = stretch.
  const std::vector<double> q = {0, 0, 0, stretch, 0, 0, stretch * L, 0, 0, stretch, 0, 0};
  const double eps = stretch * (1 + s.prestrain) - 1;
  const auto f = catena::test::element_force(cable, q, {}, 1.0);
  // End forces: −N at A, +N at B along x; no generalised slope forces for uniform strain.
  EXPECT_NEAR(f[0], -s.EA * eps, 1e-6 * s.EA * eps);
  EXPECT_NEAR(f[6], s.EA * eps, 1e-6 * s.EA * eps);
  EXPECT_NEAR(f[3], 0.0, 1e-6);
  EXPECT_NEAR(cable.section_result({q, {}, {}}).axial_force, s.EA * eps, 1e-6 * s.EA * eps);
}

TEST(AncfCable, ConstantCurvatureBendingEnergyMatchesArc) {
  // A circular arc of radius ρ has κ = 1/ρ; ∂U/∂(end slope) gives the end moment EI/ρ:
  // the generalised force on r_B,x, crossed with the unit slope, is the moment.
  // EA = 0 isolates bending: the Hermite arc is not exactly inextensible.
  CableSection s{0.0, 195.0, 1.0, 0.0, 0.0};
  const double rho = 50.0, phi = 0.02, L = rho * phi;  // short arc
  const AncfCable cable(L, s, Vec3::Zero(), Vec3::Zero());
  // Hermite interpolation of the arc (exact up to O(φ⁴)) with unit slopes.
  const Vec3 rb(rho * std::sin(phi), rho * (1 - std::cos(phi)), 0);
  const Vec3 tb(std::cos(phi), std::sin(phi), 0);
  const std::vector<double> q = {0, 0, 0, 1, 0, 0, rb[0], rb[1], rb[2], tb[0], tb[1], tb[2]};
  const auto f = catena::test::element_force(cable, q, {}, 1.0);
  const Vec3 QB(f[9], f[10], f[11]);
  const double moment = tb.cross(QB)[2];
  EXPECT_NEAR(moment, s.EI / rho, 1e-3 * s.EI / rho);
  // The section output: the couple EI/ρ about the binormal, no shear (constant moment).
  const auto section = cable.section_result({q, {}, {}});
  EXPECT_NEAR(section.bending_moment.z(), s.EI / rho, 1e-3 * s.EI / rho);
  EXPECT_LT(std::hypot(section.bending_moment.x(), section.bending_moment.y()), 1e-9);
  EXPECT_LT(section.shear_force.norm(), 1e-3 * s.EI / (rho * L));
}

// The same arc stretched uniformly by λ (positions and slopes scaled): its tangent turns
// by 1/ρ per unit reference length whatever the stretch, its curvature is 1/(λρ). The end
// moment conjugate to that turn, M = λ (t̂ × Q_B)·ẑ, is EI/ρ under the reference-length
// law (stretching leaves bending alone) and EI/(λ²ρ) under the deformed-length law, whose
// energy ½EI κ² per reference length falls as the line stretches.
TEST(AncfCable, StretchChangesTheEndMomentOnlyUnderTheDeformedLengthLaw) {
  const double rho = 50.0, phi = 0.02, L = rho * phi, stretch = 1.01;
  const Vec3 rb(rho * std::sin(phi), rho * (1 - std::cos(phi)), 0);
  const Vec3 tb(std::cos(phi), std::sin(phi), 0);
  std::vector<double> q = {0, 0, 0, 1, 0, 0, rb[0], rb[1], rb[2], tb[0], tb[1], tb[2]};
  for (double& x : q) x *= stretch;
  for (const auto law : {CurvatureMeasure::reference_length, CurvatureMeasure::deformed_length}) {
    CableSection s{0.0, 195.0, 1.0, 0.0, 0.0};
    s.curvature = law;
    const AncfCable cable(L, s, Vec3::Zero(), Vec3::Zero());
    const auto f = catena::test::element_force(cable, q, {}, 1.0);
    const double moment = stretch * tb.cross(Vec3(f[9], f[10], f[11]))[2];
    const double expected =
        law == CurvatureMeasure::reference_length ? s.EI / rho : s.EI / (stretch * stretch * rho);
    EXPECT_NEAR(moment, expected, 1e-3 * s.EI / rho) << "law " << static_cast<int>(law);
  }
}

// A tension-only (dropper) cable shortened uniformly: the force is the slack residue
// kSlackStiffness·EA·ε, without damping, and the tangent matches finite differences on
// both sides of ε = 0 (away from the kink).
TEST(AncfCable, TensionOnlyCableCarriesOnlyTheSlackResidueInCompression) {
  CableSection s = kSection;
  s.tension_only = true;
  const double L = 1.0;
  const AncfCable cable(L, s, Vec3::Zero(), Vec3::Zero());
  for (const double stretch : {0.97, 1.02}) {
    const std::vector<double> q = {0, 0, 0, 0, 0, -stretch, 0, 0, -stretch * L, 0, 0, -stretch};
    const double eps = stretch * (1 + s.prestrain) - 1;
    const double EA = eps < 0.0 ? AncfCable::kSlackStiffness * s.EA : s.EA;
    // A velocity that shortens it further: damping acts only while taut.
    const std::vector<double> v = {0, 0, 0, 0, 0, 0.1, 0, 0, 0.1, 0, 0, 0.1};
    const auto f = catena::test::element_force(cable, q, v, 1.0);
    const double rate = -0.1 * (1 + s.prestrain);  // ε̇ = a·t·u̇ along −z
    const double N = EA * (eps + (eps < 0.0 ? 0.0 : s.damping_time * rate));
    EXPECT_NEAR(f[8], -N, 1e-9 * std::abs(s.EA * eps)) << "stretch " << stretch;
    EXPECT_NEAR(cable.section_result({q, {}, {}}).axial_force, EA * eps, 1e-6 * std::abs(EA * eps));
    expect_jacobians_match(cable, q, 1e-4, 3, 1);
  }
}

// Inside the smoothing band |ε| < kSlackBand the law is C¹: the force is between the slack
// residue and EA·ε, and the tangent (damping included) matches finite differences.
TEST(AncfCable, TensionOnlyLawIsSmoothAcrossTheSlackBand) {
  CableSection s = kSection;
  s.tension_only = true;
  s.prestrain = 0.0;
  const double L = 1.0, d = AncfCable::kSlackBand;
  const AncfCable cable(L, s, Vec3::Zero(), Vec3::Zero());
  for (const double eps : {-0.5 * d, 0.0, 0.5 * d}) {
    const double stretch = 1.0 + eps;
    const std::vector<double> q = {0, 0, 0, 0, 0, -stretch, 0, 0, -stretch * L, 0, 0, -stretch};
    const double N = cable.section_result({q, {}, {}}).axial_force;
    const double smooth = (eps + d) * (eps + d) / (4.0 * d);
    EXPECT_NEAR(
        N, s.EA * ((1 - AncfCable::kSlackStiffness) * smooth + AncfCable::kSlackStiffness * eps),
        1e-9 * s.EA * d)
        << "eps " << eps;
    EXPECT_GT(N, AncfCable::kSlackStiffness * s.EA * eps);
    std::mt19937 rng(5);
    // Perturbations far below the band keep every sampling point inside it.
    const auto check = catena::test::check_element_jacobians(
        cable, perturbed(q, 1e-7, rng), perturbed(std::vector<double>(12, 0.0), 1.0, rng), 1.0,
        1e-9);
    EXPECT_LT(check.stiffness, 1e-5) << "eps " << eps;
    EXPECT_LT(check.damping, 1e-5) << "eps " << eps;
  }
}

// A slack tension-only cable whose strain varies along it (end slopes of 0.95 and 1.0, chord
// 0.97): the switch acts on the mean strain ε̄ = Σ w_k ε_k (Simpson), the variation about it
// stays elastic, N_k = EA (r ε̄ + ε_k − ε̄), r = kSlackStiffness. By hand for a straight
// element along −z: u(L/2) = 1.5 (r_B − r_A)/L − 0.25 (r_A' + r_B'), the force on r_B is
// −N_mid along z, and the slope-stretch stiffness at A is (1/6 + (4/6)/16) EA a L whatever
// the tension (∂ε̄/∂r_A' = 0 along the cable): a switch per point left it at r·EA, a mode
// with almost no inertia, and cable droppers flapped (docs/catenary.md).
TEST(AncfCable, SlackCableKeepsItsStrainVariationElastic) {
  CableSection s = kSection;
  s.tension_only = true;
  const double L = 0.5, a = 1.0 + s.prestrain;
  const AncfCable cable(L, s, Vec3::Zero(), Vec3::Zero());
  const double chord = 0.97, slope_a = 0.95, slope_b = 1.0;
  const std::vector<double> q = {0, 0, 0, 0, 0, -slope_a, 0, 0, -chord * L, 0, 0, -slope_b};
  const double eps_a = a * slope_a - 1, eps_b = a * slope_b - 1;
  const double eps_mid = a * (1.5 * chord - 0.25 * (slope_a + slope_b)) - 1;
  const double eps_mean = (eps_a + 4 * eps_mid + eps_b) / 6;
  ASSERT_LT(eps_mean, -AncfCable::kSlackBand);
  const double r = AncfCable::kSlackStiffness;
  std::vector<double> f(12), K(144);
  cable.evaluate({q, {}, {}}, {true, true, false}, {f.data(), K.data(), nullptr});
  const double N_mid = s.EA * (r * eps_mean + eps_mid - eps_mean);
  EXPECT_NEAR(f[8], -N_mid, 1e-9 * s.EA * std::abs(eps_mid - eps_mean));
  EXPECT_NEAR(K[5 * 12 + 5], (1.0 / 6 + 4.0 / 6 / 16) * s.EA * a * L, 1e-9 * s.EA * L);
  const auto section = cable.section_result({q, {}, {}});
  EXPECT_NEAR(section.axial_strain, eps_mean, 1e-14);
  EXPECT_NEAR(section.axial_force, r * s.EA * eps_mean, 1e-9 * r * s.EA);
  expect_jacobians_match(cable, q, 1e-3, 11, 4);
}

// A taut tension-only cable with the same uneven strain carries N_k = EA ε_k, as a linear
// section does, and its tangent (damping included) matches finite differences.
TEST(AncfCable, TautTensionOnlyCableMatchesTheLinearSection) {
  CableSection s = kSection;
  s.tension_only = true;
  CableSection linear = kSection;
  const double L = 0.5;
  const AncfCable cable(L, s, Vec3::Zero(), Vec3::Zero()),
      reference(L, linear, Vec3::Zero(), Vec3::Zero());
  const std::vector<double> q = {0, 0, 0, 0, 0, -1.01, 0, 0, -1.02 * L, 0, 0, -1.03};
  const std::vector<double> v = {0, 0, 0, 0, 0, -0.1, 0, 0, -0.2, 0, 0, 0.05};
  const auto f = catena::test::element_force(cable, q, v, 1.0);
  const auto f_linear = catena::test::element_force(reference, q, v, 1.0);
  for (int i = 0; i < 12; ++i) EXPECT_NEAR(f[i], f_linear[i], 1e-9 * s.EA) << "dof " << i;
  std::mt19937 rng(13);
  const auto check = catena::test::check_element_jacobians(cable, perturbed(q, 1e-3, rng), v, 1.0);
  EXPECT_LT(check.stiffness, 1e-6);
  EXPECT_LT(check.damping, 1e-6);
}

// prestrain_with_loads: along the static load path the prestrain is ε_p·loads, whatever
// the path's tensioning and release factors; at the path's end it is ε_p, as for any cable.
TEST(AncfCable, PrestrainPutOnWithTheLoads) {
  CableSection s = kSection;
  s.damping_time = 0.0;
  s.prestrain = 0.4;  // a dropper shortened to L/1.4 by shape finding
  s.prestrain_with_loads = true;
  const double L = 1.0;
  const AncfCable cable(L, s, Vec3::Zero(), Vec3::Zero());
  const std::vector<double> q = {0, 0, 0, 1, 0, 0, L, 0, 0, 1, 0, 0};  // mesh length
  for (const double loads : {0.0, 0.25, 1.0}) {
    const catena::elements::LoadPath path(1.0, loads, 0.0);
    EXPECT_DOUBLE_EQ(AncfCable::section_prestrain(s, path), s.prestrain * loads);
    EXPECT_NEAR(cable.section_result({q, {}, path}).axial_force, s.EA * s.prestrain * loads,
                1e-9 * s.EA)
        << "loads " << loads;
  }
  s.prestrain_with_loads = false;  // a wire: tensioned first (path.prestrain), loads aside
  EXPECT_DOUBLE_EQ(AncfCable::section_prestrain(s, catena::elements::LoadPath(1.0, 0.0, 0.0)),
                   s.prestrain);
}
