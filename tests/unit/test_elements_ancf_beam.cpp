// ANCF beam kernel (ancf_beam.hpp): exact Jacobians vs central finite differences,
// rigid-motion invariance and objectivity, rigid-body modes only, closed-form mass matrix,
// external loads, and patch tests (uniform stretch, uniform twist, pure bending).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <cmath>
#include <random>

#include "catena/elements/ancf_beam.hpp"
#include "dense_statics.hpp"
#include "element_checks.hpp"

using catena::Mat3;
using catena::Vec3;
using catena::elements::AncfBeam;
using catena::elements::BeamLoads;
using catena::elements::BeamNodeRef;
using catena::elements::BeamSection;
using catena::elements::SectionResult;

namespace {

constexpr int kN = AncfBeam::kDofs;
using MatK = Eigen::Matrix<double, kN, kN, Eigen::RowMajor>;
using VecK = Eigen::Matrix<double, kN, 1>;

// Moderate stiffness ratios keep finite differences accurate; every term is active.
BeamSection test_section() {
  BeamSection s;
  s.EA = 2.0e4;
  s.GA_y = 6.0e3;
  s.GA_z = 7.0e3;
  s.GJ = 9.0;
  s.EI_y = 15.0;
  s.EI_z = 6.0;
  s.mass_per_length = 2.5;
  s.rho_Iy = 0.03;
  s.rho_Iz = 0.012;
  s.damping_time = 0.01;
  return s;
}

const BeamLoads kLoads{Vec3(0, 0, -9.81), Vec3(1.0, -2.0, 0.5)};

// Node with tangent t and a section frame rotated by `roll` about t from a frame built
// with `up` as the reference z direction.
BeamNodeRef node(const Vec3& r, const Vec3& t, const Vec3& up = Vec3::UnitZ(), double roll = 0) {
  const Vec3 tn = t.normalized();
  Vec3 dz = (up - up.dot(tn) * tn).normalized();
  Vec3 dy = dz.cross(tn);
  const Eigen::AngleAxisd rot(roll, tn);
  return {r, tn, rot * dy, rot * dz};
}

// A straight element of length 1.3 along an oblique direction.
AncfBeam straight_beam(const BeamSection& s = test_section(), const BeamLoads& l = kLoads) {
  const Vec3 a(0.2, -0.1, 0.4), dir = Vec3(1.0, 0.4, -0.3).normalized();
  return AncfBeam(node(a, dir, Vec3::UnitZ(), 0.3), node(a + 1.3 * dir, dir, Vec3::UnitZ(), 0.3), s,
                  l);
}

// A curved, pre-twisted reference: end tangents and rolls differ.
AncfBeam curved_beam(const BeamSection& s = test_section(), const BeamLoads& l = kLoads) {
  return AncfBeam(node(Vec3(0, 0, 0), Vec3(1, 0.3, 0.1), Vec3::UnitZ(), 0.1),
                  node(Vec3(0.9, 0.4, -0.1), Vec3(0.8, 0.6, -0.3), Vec3::UnitZ(), 0.5), s, l);
}

std::vector<double> to_vector(const std::array<double, kN>& a) { return {a.begin(), a.end()}; }

std::vector<double> perturbed(std::vector<double> q, double amplitude, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-amplitude, amplitude);
  for (double& x : q) x += u(rng);
  return q;
}

// Applies x ↦ R x + c (c on the two position blocks only) to a state.
std::vector<double> rigidly_moved(const std::vector<double>& q, const Mat3& R, const Vec3& c) {
  std::vector<double> out(q.size());
  for (int b = 0; b < kN / 3; ++b) {
    Vec3 x = R * Vec3(q[3 * b], q[3 * b + 1], q[3 * b + 2]);
    if (b % 4 == 0) x += c;
    for (int k = 0; k < 3; ++k) out[3 * b + k] = x[k];
  }
  return out;
}

Mat3 random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  const Vec3 axis = Vec3(n(rng), n(rng), n(rng)).normalized();
  return Eigen::AngleAxisd(2.5, axis).toRotationMatrix();
}

struct Evaluation {
  std::vector<double> f, K, C;
};

Evaluation evaluate(const AncfBeam& e, const std::vector<double>& q,
                    const std::vector<double>& v = {}, double load_factor = 1.0) {
  Evaluation out{std::vector<double>(kN), std::vector<double>(kN * kN),
                 std::vector<double>(kN * kN)};
  e.evaluate({q, v, catena::elements::LoadPath(load_factor)}, {true, true, true},
             {out.f.data(), out.K.data(), out.C.data()});
  return out;
}

double max_abs(const std::vector<double>& x) {
  double m = 0.0;
  for (double y : x) m = std::max(m, std::abs(y));
  return m;
}

Vec3 block(const std::vector<double>& x, int b) { return {x[3 * b], x[3 * b + 1], x[3 * b + 2]}; }
void set_block(std::vector<double>& x, int b, const Vec3& v) {
  for (int k = 0; k < 3; ++k) x[3 * b + k] = v[k];
}
// Block indices of the 24-vector: [r_A, r_A,x, r_A,y, r_A,z, r_B, r_B,x, r_B,y, r_B,z].
enum { kRA = 0, kRxA, kRyA, kRzA, kRB, kRxB, kRyB, kRzB };

}  // namespace

// Tolerance 1e-6: central differences with h = 1e-6 have truncation error ~h²·|f'''| and
// round-off ~1e-16·|f|/h ≈ 1e-10 relative; the analytic K and C are exact to round-off.
TEST(AncfBeam, JacobiansMatchFiniteDifferencesAtRandomStates) {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> lambda(0.1, 1.0);
  double worst_K = 0.0, worst_C = 0.0;
  BeamSection deformed_law = test_section();
  deformed_law.curvature = catena::CurvatureMeasure::deformed_length;
  for (const AncfBeam& beam :
       {straight_beam(), curved_beam(), straight_beam(deformed_law), curved_beam(deformed_law)}) {
    for (int trial = 0; trial < 6; ++trial) {
      const auto q = perturbed(to_vector(beam.reference_state()), 0.08, rng);
      const auto v = perturbed(std::vector<double>(kN, 0.0), 1.0, rng);
      const auto check = catena::test::check_element_jacobians(beam, q, v, lambda(rng));
      EXPECT_LT(check.stiffness, 1e-6) << "trial " << trial;
      EXPECT_LT(check.damping, 1e-6) << "trial " << trial;
      worst_K = std::max(worst_K, check.stiffness);
      worst_C = std::max(worst_C, check.damping);
    }
  }
  RecordProperty("worst_K_fd_difference", std::to_string(worst_K));
  RecordProperty("worst_C_fd_difference", std::to_string(worst_C));
  std::printf("max relative FD difference: K %.2e, C %.2e\n", worst_K, worst_C);
}

TEST(AncfBeam, StiffnessIsSymmetricWithoutVelocity) {
  std::mt19937 rng(5);
  const AncfBeam beam = curved_beam();
  const auto q = perturbed(to_vector(beam.reference_state()), 0.1, rng);
  const auto e = evaluate(beam, q);
  const Eigen::Map<const MatK> K(e.K.data()), C(e.C.data());
  EXPECT_LT((K - K.transpose()).cwiseAbs().maxCoeff(), 1e-12 * K.cwiseAbs().maxCoeff());
  EXPECT_LT((C - C.transpose()).cwiseAbs().maxCoeff(), 1e-12 * C.cwiseAbs().maxCoeff());
  // C = τ Σ k_i g_i g_iᵀ is positive semi-definite.
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(Eigen::MatrixXd(C.transpose() + C) / 2);
  EXPECT_GT(eig.eigenvalues().minCoeff(), -1e-12 * C.cwiseAbs().maxCoeff());
}

TEST(AncfBeam, ZeroInternalForceUnderRigidMotionOfReference) {
  std::mt19937 rng(11);
  const BeamLoads no_loads{};
  for (const AncfBeam& beam :
       {straight_beam(test_section(), no_loads), curved_beam(test_section(), no_loads)}) {
    const auto q_ref = to_vector(beam.reference_state());
    EXPECT_LT(max_abs(evaluate(beam, q_ref).f), 1e-10);
    for (int trial = 0; trial < 3; ++trial) {
      const auto q = rigidly_moved(q_ref, random_rotation(rng), Vec3(3.0, -1.0, 2.0));
      // Forces are EA·(strain); round-off in the strains is ~1e-16.
      EXPECT_LT(max_abs(evaluate(beam, q).f), 1e-10 * test_section().EA);
      EXPECT_LT(beam.strain_energy(q), 1e-20 * test_section().EA);
      // A rigid velocity field does no damping work: objective strain rates vanish.
      const Vec3 omega(0.3, -1.2, 0.7), c_dot(1.0, 2.0, -0.5);
      std::vector<double> v(kN);
      for (int b = 0; b < kN / 3; ++b)
        set_block(v, b, omega.cross(block(q, b)) + (b % 4 == 0 ? c_dot : Vec3::Zero()));
      EXPECT_LT(max_abs(evaluate(beam, q, v).f), 1e-10 * test_section().EA);
    }
  }
}

TEST(AncfBeam, EnergyForceAndStiffnessAreObjective) {
  std::mt19937 rng(3);
  const BeamLoads no_loads{};
  const AncfBeam beam = curved_beam(test_section(), no_loads);
  for (int trial = 0; trial < 3; ++trial) {
    const auto q = perturbed(to_vector(beam.reference_state()), 0.1, rng);
    const Mat3 R = random_rotation(rng);
    const auto q_rot = rigidly_moved(q, R, Vec3(-2.0, 0.5, 1.0));
    EXPECT_NEAR(beam.strain_energy(q_rot), beam.strain_energy(q), 1e-11 * beam.strain_energy(q));
    const auto e = evaluate(beam, q), e_rot = evaluate(beam, q_rot);
    // f(Rq + c) = (I ⊗ R) f(q),  K(Rq + c) = (I ⊗ R) K(q) (I ⊗ R)ᵀ.
    MatK Q = MatK::Zero();
    for (int b = 0; b < kN / 3; ++b) Q.block<3, 3>(3 * b, 3 * b) = R;
    const VecK f_expected = Q * Eigen::Map<const VecK>(e.f.data());
    EXPECT_LT((Eigen::Map<const VecK>(e_rot.f.data()) - f_expected).cwiseAbs().maxCoeff(),
              1e-10 * max_abs(e.f));
    const MatK K_expected = Q * Eigen::Map<const MatK>(e.K.data()) * Q.transpose();
    EXPECT_LT((Eigen::Map<const MatK>(e_rot.K.data()) - K_expected).cwiseAbs().maxCoeff(),
              1e-10 * max_abs(e.K));
  }
}

// No spurious zero-energy modes: the reference stiffness has exactly the 6 rigid modes.
TEST(AncfBeam, ReferenceStiffnessHasExactlySixZeroModes) {
  for (const AncfBeam& beam : {straight_beam(), curved_beam()}) {
    const auto e = evaluate(beam, to_vector(beam.reference_state()));
    const Eigen::Map<const MatK> K(e.K.data());
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(Eigen::MatrixXd(K.transpose() + K) / 2);
    const Eigen::VectorXd lambda = eig.eigenvalues();
    const double scale = lambda.cwiseAbs().maxCoeff();
    for (int i = 0; i < 6; ++i) EXPECT_LT(std::abs(lambda[i]), 1e-10 * scale) << i;
    // The softest deformation mode (twist, GJ/L) is ~1e-5 of the stiffest (EA/L).
    EXPECT_GT(lambda[6], 1e-7 * scale);
  }
}

// The same for an assembled, unsupported chain: no global hourglass mode either (with the
// axial strain at 2 Gauss points, stretching every slope alike would cost no energy).
TEST(AncfBeam, FreeChainHasOnlyRigidModes) {
  const int n_elements = 4;
  const Vec3 dir = Vec3(1.0, 0.4, -0.3).normalized();
  std::vector<BeamNodeRef> nodes;
  for (int i = 0; i <= n_elements; ++i) nodes.push_back(node(0.4 * i * dir, dir));
  std::vector<AncfBeam> beams;
  for (int e = 0; e < n_elements; ++e)
    beams.emplace_back(nodes[e], nodes[e + 1], test_section(), BeamLoads{});
  catena::test::DenseStaticsProblem p;
  p.dofs_per_node.assign(n_elements + 1, AncfBeam::kDofsPerNode);
  for (int e = 0; e < n_elements; ++e) p.elements.push_back({&beams[e], {e, e + 1}});
  for (const BeamNodeRef& n : nodes)
    for (const Vec3& b : {n.r, n.t, n.d_y, n.d_z}) p.q0.insert(p.q0.end(), b.data(), b.data() + 3);
  std::vector<double> K;
  catena::test::assemble_residual(p, p.q0, 1.0, &K);
  const int n = static_cast<int>(p.q0.size());
  const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> Km(
      K.data(), n, n);
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(Eigen::MatrixXd(Km.transpose() + Km) / 2);
  const Eigen::VectorXd lambda = eig.eigenvalues();
  const double scale = lambda.cwiseAbs().maxCoeff();
  for (int i = 0; i < 6; ++i) EXPECT_LT(std::abs(lambda[i]), 1e-10 * scale) << i;
  EXPECT_GT(lambda[6], 1e-7 * scale);
}

TEST(AncfBeam, MassMatrixMatchesClosedForm) {
  const BeamSection s = test_section();
  const AncfBeam beam = straight_beam();
  const double L = beam.length(), rhoA = s.mass_per_length;
  std::vector<double> Mv(kN * kN);
  beam.mass(Mv.data());
  const Eigen::Map<const MatK> M(Mv.data());
  EXPECT_LT((M - M.transpose()).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_EQ(Eigen::LLT<Eigen::MatrixXd>(Eigen::MatrixXd(M)).info(), Eigen::Success);

  // Centreline: ρA·L/420·[156 22L 54 −13L; 22L 4L² 13L −3L²; 54 13L 156 −22L;
  // −13L −3L² −22L 4L²] ⊗ I₃ on blocks (r_A, r_A,x, r_B, r_B,x).
  const double h[4][4] = {{156, 22 * L, 54, -13 * L},
                          {22 * L, 4 * L * L, 13 * L, -3 * L * L},
                          {54, 13 * L, 156, -22 * L},
                          {-13 * L, -3 * L * L, -22 * L, 4 * L * L}};
  const int centre[4] = {kRA, kRxA, kRB, kRxB};
  // Directors: ρI_z (for d_y) and ρI_y (for d_z) times the linear mass L/6·[2 1; 1 2].
  const int dy[2] = {kRyA, kRyB}, dz[2] = {kRzA, kRzB};
  MatK expected = MatK::Zero();
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      expected.block<3, 3>(3 * centre[a], 3 * centre[b]) =
          rhoA * L / 420.0 * h[a][b] * Mat3::Identity();
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      const double lin = L / 6.0 * (a == b ? 2.0 : 1.0);
      expected.block<3, 3>(3 * dy[a], 3 * dy[b]) = s.rho_Iz * lin * Mat3::Identity();
      expected.block<3, 3>(3 * dz[a], 3 * dz[b]) = s.rho_Iy * lin * Mat3::Identity();
    }
  EXPECT_LT((M - expected).cwiseAbs().maxCoeff(), 1e-14 * rhoA * L);

  // Total mass from a unit translation.
  VecK T = VecK::Zero();
  T.segment<3>(3 * kRA) = T.segment<3>(3 * kRB) = Vec3(0.6, 0.0, 0.8);
  EXPECT_NEAR(T.dot(M * T), rhoA * L, 1e-13 * rhoA * L);
  // Rotary inertia about the axis: rotating the section at rate ω about t gives ½ρJ ω² L.
  VecK W = VecK::Zero();
  const auto q = to_vector(beam.reference_state());
  const Vec3 t = block(q, kRxA);
  for (int b : {kRyA, kRzA, kRyB, kRzB}) W.segment<3>(3 * b) = t.cross(block(q, b));
  EXPECT_NEAR(W.dot(M * W), (s.rho_Iy + s.rho_Iz) * L, 1e-13);
}

TEST(AncfBeam, ExternalLoadsIntegrateToTheResultant) {
  const BeamSection s = test_section();
  const AncfBeam beam = straight_beam();
  const auto q = to_vector(beam.reference_state());
  const double lambda = 0.7;
  std::vector<double> f(kN);
  beam.evaluate({q, {}, catena::elements::LoadPath(lambda)}, {true, false, false},
                {f.data(), nullptr, nullptr});
  const Vec3 resultant = block(f, kRA) + block(f, kRB);
  const Vec3 expected =
      -lambda * beam.length() * (s.mass_per_length * kLoads.gravity + kLoads.distributed);
  EXPECT_LT((resultant - expected).norm(), 1e-12 * expected.norm());
  // Consistent moments on the slopes: ±L²/12 of the resultant per length.
  EXPECT_LT((block(f, kRxA) + block(f, kRxB)).norm(), 1e-12 * expected.norm());
  EXPECT_LT((block(f, kRxA) - expected * beam.length() / 12.0).norm(), 1e-12 * expected.norm());
}

// Uniform stretch by ε (any size): N = EA ε, f_rB = −f_rA = EA ε t, no slope forces.
TEST(AncfBeam, PatchUniformStretch) {
  const BeamSection s = test_section();
  const AncfBeam beam = straight_beam(s, BeamLoads{});
  auto q = to_vector(beam.reference_state());
  const Vec3 t = block(q, kRxA);
  const double L = beam.length();
  for (double eps : {1e-4, 0.05, -0.02}) {
    auto qs = q;
    set_block(qs, kRB, block(q, kRA) + (1.0 + eps) * L * t);
    set_block(qs, kRxA, (1.0 + eps) * t);
    set_block(qs, kRxB, (1.0 + eps) * t);
    const auto e = evaluate(beam, qs);
    const double N = s.EA * eps;
    EXPECT_LT((block(e.f, kRB) - N * t).norm(), 1e-10 * s.EA);
    EXPECT_LT((block(e.f, kRA) + N * t).norm(), 1e-10 * s.EA);
    for (int b : {kRxA, kRxB, kRyA, kRzA, kRyB, kRzB})
      EXPECT_LT(block(e.f, b).norm(), 1e-10 * s.EA) << b;
    const auto sr = beam.section_result({qs, {}, {}});
    EXPECT_NEAR(sr.axial_strain, eps, 1e-14);
    EXPECT_NEAR(sr.axial_force, N, 1e-10 * s.EA);
    EXPECT_NEAR(beam.strain_energy(qs), 0.5 * s.EA * eps * eps * L, 1e-12 * s.EA);
  }
}

// Uniform twist: node B's section frame turned by φ about t. The element twist angle is
// exact for any φ, so E = ½ GJ φ² / L and the torque about t,
// T = f_ry·(t × d_y) + f_rz·(t × d_z) = dE/dφ = GJ φ / L (equal and opposite at A).
TEST(AncfBeam, PatchUniformTwist) {
  const BeamSection s = test_section();
  const AncfBeam beam = straight_beam(s, BeamLoads{});
  const auto q = to_vector(beam.reference_state());
  const Vec3 t = block(q, kRxA);
  const double L = beam.length();
  for (double phi : {1e-5, 0.3, 1.2, 2.5}) {
    auto qs = q;
    const Eigen::AngleAxisd turn(phi, t);
    set_block(qs, kRyB, turn * block(q, kRyB));
    set_block(qs, kRzB, turn * block(q, kRzB));
    const auto e = evaluate(beam, qs);
    const double torque = block(e.f, kRyB).dot(t.cross(block(qs, kRyB))) +
                          block(e.f, kRzB).dot(t.cross(block(qs, kRzB)));
    const double torque_a = block(e.f, kRyA).dot(t.cross(block(qs, kRyA))) +
                            block(e.f, kRzA).dot(t.cross(block(qs, kRzA)));
    EXPECT_NEAR(torque, s.GJ * phi / L, 1e-12 * s.GJ) << phi;
    EXPECT_NEAR(torque_a, -torque, 1e-12 * s.GJ) << phi;
    EXPECT_NEAR(beam.strain_energy(qs), 0.5 * s.GJ * phi * phi / L, 1e-12 * s.GJ) << phi;
    // The section output: the torsion, no bending couple, no section force.
    const SectionResult sr = beam.section_result({qs, {}, {}});
    EXPECT_NEAR(sr.torsion, s.GJ * phi / L, 1e-12 * s.GJ) << phi;
    EXPECT_LT(sr.bending_moment.norm() + sr.shear_force.norm(), 1e-9 * s.GJ) << phi;
    // Pure torque: no force on the centreline, none stretching or shearing the frame.
    for (int b : {kRA, kRxA, kRB, kRxB}) EXPECT_LT(block(e.f, b).norm(), 1e-12 * s.GJ) << b;
    for (int b : {kRyA, kRzA, kRyB, kRzB}) EXPECT_LT(std::abs(block(e.f, b).dot(t)), 1e-12 * s.GJ);
  }
}

// Pure bending (linear patch): the curvature field κ x e_n with the section frame turning
// with the tangent, x ∈ [0, L]. The reference stiffness maps it to the end moments
// ∓EI κ on the slopes and nothing else; bending about y (curvature in the x–z plane,
// deflection along d_z) uses EI_y, bending about z (deflection along d_y) uses EI_z.
TEST(AncfBeam, PatchPureBendingAboutBothAxes) {
  const BeamSection s = test_section();
  const AncfBeam beam = straight_beam(s, BeamLoads{});
  const auto q = to_vector(beam.reference_state());
  const Vec3 t = block(q, kRxA), d_y = block(q, kRyA), d_z = block(q, kRzA);
  const double L = beam.length(), kappa = 1.0;
  const auto e = evaluate(beam, q);
  const Eigen::Map<const MatK> K(e.K.data());
  struct Case {
    Vec3 deflection;  // direction of the displacement κx²/2
    double EI;
  };
  for (const Case& c : {Case{d_z, s.EI_y}, Case{d_y, s.EI_z}}) {
    // Linearised: w(x) = κx²/2 n, slope κx n; the frame turns by κx about t × n, so the
    // director along n gets −κx t (the other director is unchanged).
    VecK dq = VecK::Zero();
    dq.segment<3>(3 * kRB) = 0.5 * kappa * L * L * c.deflection;
    dq.segment<3>(3 * kRxB) = kappa * L * c.deflection;
    const int director_b = c.deflection.dot(d_z) > 0.5 ? kRzB : kRyB;
    dq.segment<3>(3 * director_b) = -kappa * L * t;
    const VecK f = K * dq;
    EXPECT_LT((f.segment<3>(3 * kRxB) - c.EI * kappa * c.deflection).norm(), 1e-10 * c.EI);
    EXPECT_LT((f.segment<3>(3 * kRxA) + c.EI * kappa * c.deflection).norm(), 1e-10 * c.EI);
    for (int b : {kRA, kRB, kRyA, kRzA, kRyB, kRzB})
      EXPECT_LT(f.segment<3>(3 * b).norm(), 1e-10 * c.EI) << b;
  }
}

TEST(AncfBeam, SectionResultIncludesKelvinVoigtRate) {
  const BeamSection s = test_section();
  const AncfBeam beam = straight_beam(s, BeamLoads{});
  const auto q = to_vector(beam.reference_state());
  const Vec3 t = block(q, kRxA);
  std::vector<double> v(kN, 0.0);
  // Stretch rate ε̇: node B moves along t at ε̇ L, slopes grow at ε̇.
  const double eps_dot = 0.2;
  set_block(v, kRB, eps_dot * beam.length() * t);
  set_block(v, kRxA, eps_dot * t);
  set_block(v, kRxB, eps_dot * t);
  const auto sr = beam.section_result({q, v, {}});
  EXPECT_NEAR(sr.axial_strain, 0.0, 1e-15);
  EXPECT_NEAR(sr.axial_force, s.EA * s.damping_time * eps_dot, 1e-10 * s.EA);
}
