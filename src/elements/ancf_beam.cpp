#include "catena/elements/ancf_beam.hpp"

#include <Eigen/Core>
#include <cmath>

#include "ancf_beam_strains.hpp"
#include "catena/core/error.hpp"
#include "catena/elements/dual.hpp"
#include "catena/elements/hermite.hpp"

namespace catena::elements {
namespace {

namespace bs = beam_strains;

constexpr int kDofs = AncfBeam::kDofs;
// The element DOF vector is 8 blocks of 3 (ancf_beam.hpp): block index of each quantity.
constexpr int kBlocks = 8;
enum Block : int { kRA = 0, kRxA, kRyA, kRzA, kRB, kRxB, kRyB, kRzB };

using Vec24 = Eigen::Matrix<double, kDofs, 1>;
using Mat24 = Eigen::Matrix<double, kDofs, kDofs>;

// A point of one strain group: its N/3 local 3-vector arguments are linear combinations of
// the 8 DOF blocks, argument I = Σ_J b[I][J] · block J (so the map is b ⊗ I₃).
template <int N>
struct PointMap {
  std::array<std::array<double, kBlocks>, N / 3> b{};

  Eigen::Matrix<double, N, kDofs> matrix() const {
    Eigen::Matrix<double, N, kDofs> B = Eigen::Matrix<double, N, kDofs>::Zero();
    for (int I = 0; I < N / 3; ++I)
      for (int J = 0; J < kBlocks; ++J)
        if (b[I][J] != 0.0) B.template block<3, 3>(3 * I, 3 * J).diagonal().setConstant(b[I][J]);
    return B;
  }
  std::array<double, N> gather(const double* q) const {
    std::array<double, N> x{};
    for (int I = 0; I < N / 3; ++I)
      for (int J = 0; J < kBlocks; ++J)
        for (int c = 0; c < 3; ++c) x[3 * I + c] += b[I][J] * q[3 * J + c];
    return x;
  }
};

// Axial group [r_c'] at x = ξL.
PointMap<3> axial_map(double xi, double L) {
  const HermiteAt h = hermite_at(xi * L, L);
  PointMap<3> m;
  m.b[0] = {h.ds[0], h.ds[1], 0, 0, h.ds[2], h.ds[3], 0, 0};
  return m;
}

// Bending group [r_c', r_c'', d_y, d_z] at x = ξL.
PointMap<12> bending_map(double xi, double L) {
  const HermiteAt h = hermite_at(xi * L, L);
  PointMap<12> m;
  m.b[0] = {h.ds[0], h.ds[1], 0, 0, h.ds[2], h.ds[3], 0, 0};
  m.b[1] = {h.dds[0], h.dds[1], 0, 0, h.dds[2], h.dds[3], 0, 0};
  m.b[2][kRyA] = 1.0 - xi;
  m.b[2][kRyB] = xi;
  m.b[3][kRzA] = 1.0 - xi;
  m.b[3][kRzB] = xi;
  return m;
}

// Twist group [d_y,A, d_z,A, d_y,B, d_z,B] (element-constant).
PointMap<12> twist_map() {
  PointMap<12> m;
  m.b[0][kRyA] = m.b[1][kRzA] = m.b[2][kRyB] = m.b[3][kRzB] = 1.0;
  return m;
}

// Nodal group [r_x, d_y, d_z] at node 0 (A) or 1 (B).
PointMap<9> node_map(int node) {
  PointMap<9> m;
  const int first = node == 0 ? kRA : kRB;
  m.b[0][first + 1] = 1.0;
  m.b[1][first + 2] = 1.0;
  m.b[2][first + 3] = 1.0;
  return m;
}

// Quadrature rules on ξ = x/L ∈ [0, 1], weights as fractions of L.
struct Rule01 {
  double xi, w;
};
// Lobatto 3 (Simpson): exact for cubics; the axial samples (ancf_beam.hpp: why).
constexpr std::array<Rule01, 3> kLobatto3 = {
    {{0.0, 1.0 / 6.0}, {0.5, 4.0 / 6.0}, {1.0, 1.0 / 6.0}}};
Rule01 gauss01(int n, int g) {
  return {0.5 * (1.0 + gauss_points(n)[g]), 0.5 * gauss_weights(n)[g]};
}

// Strain functions of each group, callable with any scalar.
struct AxialGroup {
  template <class S>
  std::array<S, 1> operator()(const std::array<S, 3>& x) const {
    return bs::axial_strain(x);
  }
};
struct BendingGroup {
  bool per_deformed_length;
  template <class S>
  std::array<S, 2> operator()(const std::array<S, 12>& x) const {
    return bs::bending_strains(x, per_deformed_length);
  }
};
// κ_x = φ/L with the element twist angle φ: energy ½ GJ κ_x² L.
struct TwistGroup {
  double inv_length;
  template <class S>
  std::array<S, 1> operator()(const std::array<S, 12>& x) const {
    return {bs::twist_angle(x)[0] * inv_length};
  }
};
struct NodeGroup {
  template <class S>
  std::array<S, 5> operator()(const std::array<S, 9>& x) const {
    return bs::node_strains(x);
  }
};

// Element totals in DOF space (only the requested blocks are accumulated).
struct Accumulator {
  Request request;
  Vec24 f = Vec24::Zero();
  Mat24 K = Mat24::Zero();
  Mat24 C = Mat24::Zero();
};

// Per strain measure e_i (stiffness k_i, reference value e_i,ref), with the generalized
// Kelvin–Voigt stress σ_i = k_i (e_i − e_i,ref + τ ė_i), ė_i = g_i·ẋ, g_i = ∂e_i/∂x,
// H_i = ∂²e_i/∂x² (x: the point's local arguments, ẋ their rates):
//   f += w σ_i g_i
//   K += w [k_i (g_i g_iᵀ + τ g_i (H_i ẋ)ᵀ) + σ_i H_i]      (∂f/∂x)
//   C += w τ k_i g_i g_iᵀ                                    (∂f/∂ẋ)
// then mapped to the DOFs by x = B q (B constant): f_q = Bᵀ f_x, K_q = Bᵀ K_x B.
template <int N, std::size_t M, class Group>
void add_point(const PointMap<N>& map, double weight, const std::array<double, M>& k,
               const double* e_ref, double tau, const double* q, const double* v, Group group,
               Accumulator& acc) {
  using VecN = Eigen::Matrix<double, N, 1>;
  using MatN = Eigen::Matrix<double, N, N>;
  const std::array<double, N> x = map.gather(q);
  VecN x_dot = VecN::Zero();
  if (v != nullptr) x_dot = Eigen::Map<const VecN>(map.gather(v).data());

  VecN f_x = VecN::Zero();
  MatN K_x = MatN::Zero(), C_x = MatN::Zero();
  const auto add_first_order = [&](std::size_t i, double e, const VecN& g) {
    const double e_dot = g.dot(x_dot);
    const double sigma = k[i] * (e - e_ref[i] + tau * e_dot);
    f_x += (weight * sigma) * g;
    if (acc.request.stiffness) K_x.noalias() += (weight * k[i]) * g * g.transpose();
    if (acc.request.damping) C_x.noalias() += (weight * tau * k[i]) * g * g.transpose();
    return sigma;
  };

  if (acc.request.stiffness) {
    std::array<Dual2<N>, N> xs;
    for (int j = 0; j < N; ++j) xs[j] = Dual2<N>::variable(x[j], j);
    const auto e = group(xs);
    for (std::size_t i = 0; i < M; ++i) {
      const VecN g = Eigen::Map<const VecN>(e[i].g.data());
      MatN H;
      for (int a = 0; a < N; ++a)
        for (int b = a; b < N; ++b) H(a, b) = H(b, a) = e[i].hess(a, b);
      const double sigma = add_first_order(i, e[i].v, g);
      K_x += (weight * sigma) * H;
      if (tau != 0.0 && v != nullptr)
        K_x.noalias() += (weight * tau * k[i]) * g * (H * x_dot).transpose();
    }
  } else {
    std::array<Dual1<N>, N> xs;
    for (int j = 0; j < N; ++j) xs[j] = Dual1<N>::variable(x[j], j);
    const auto e = group(xs);
    for (std::size_t i = 0; i < M; ++i)
      add_first_order(i, e[i].v, Eigen::Map<const VecN>(e[i].g.data()));
  }

  const Eigen::Matrix<double, N, kDofs> B = map.matrix();
  acc.f.noalias() += B.transpose() * f_x;
  if (acc.request.stiffness) acc.K.noalias() += B.transpose() * (K_x * B);
  if (acc.request.damping) acc.C.noalias() += B.transpose() * (C_x * B);
}

void put_block(std::array<double, kDofs>& q, int block, const Vec3& value) {
  for (int c = 0; c < 3; ++c) q[3 * block + c] = value[c];
}

}  // namespace

template <class Visitor>
void AncfBeam::for_each_point(Visitor&& visit) const {
  const double L = length_;
  const BeamSection& sec = section_;
  int sample = 0;
  const auto point = [&](const auto& map, double weight, const auto& k, auto group) {
    visit(map, weight, k, sample, group);
    sample += static_cast<int>(k.size());
  };
  for (const Rule01& p : kLobatto3)
    point(axial_map(p.xi, L), p.w * L, std::array{sec.EA}, AxialGroup{});
  for (int g = 0; g < kBendingPoints; ++g) {
    const Rule01 p = gauss01(kBendingPoints, g);
    point(bending_map(p.xi, L), p.w * L, std::array{sec.EI_y, sec.EI_z},
          BendingGroup{sec.curvature == CurvatureMeasure::deformed_length});
  }
  point(twist_map(), L, std::array{sec.GJ}, TwistGroup{1.0 / L});
  for (int n = 0; n < kNodes; ++n)
    point(node_map(n), 0.5 * L, std::array{sec.GA_y, sec.GA_z, sec.EA, sec.EA, sec.EA},
          NodeGroup{});
  CATENA_ASSERT(sample == kStrainSamples, "AncfBeam: strain sample count");
}

AncfBeam::AncfBeam(const BeamNodeRef& node_a, const BeamNodeRef& node_b, const BeamSection& section,
                   const BeamLoads& loads)
    : length_((node_b.r - node_a.r).norm()), section_(section) {
  CATENA_ASSERT(length_ > 0.0, "AncfBeam: coincident nodes");
  for (const BeamNodeRef* n : {&node_a, &node_b}) {
    CATENA_ASSERT(std::abs(n->t.norm() - 1.0) < 1e-8 && std::abs(n->d_y.norm() - 1.0) < 1e-8 &&
                      std::abs(n->d_z.norm() - 1.0) < 1e-8,
                  "AncfBeam: nodal frame vectors must be unit");
    CATENA_ASSERT((n->t.cross(n->d_y) - n->d_z).norm() < 1e-8,
                  "AncfBeam: nodal frame must be orthonormal and right-handed");
    (void)n;
  }
  put_block(q_ref_, kRA, node_a.r);
  put_block(q_ref_, kRxA, node_a.t);
  put_block(q_ref_, kRyA, node_a.d_y);
  put_block(q_ref_, kRzA, node_a.d_z);
  put_block(q_ref_, kRB, node_b.r);
  put_block(q_ref_, kRxB, node_b.t);
  put_block(q_ref_, kRyB, node_b.d_y);
  put_block(q_ref_, kRzB, node_b.d_z);

  // Reference strains: the reference configuration is stress free even when curved.
  std::array<double, kStrainSamples>& e_ref = e_ref_;
  for_each_point([&](const auto& map, double, const auto&, int first, auto group) {
    const auto e = group(map.gather(q_ref_.data()));
    for (std::size_t i = 0; i < e.size(); ++i) e_ref[first + i] = e[i];
  });

  const double L = length_;
  // f_ext = ∫ S_cᵀ p dx with p = ρA g + q constant: ∫S = (L/2, L²/12, L/2, −L²/12).
  const Vec3 p = section.mass_per_length * loads.gravity + loads.distributed;
  f_ext_.fill(0.0);
  put_block(f_ext_, kRA, 0.5 * L * p);
  put_block(f_ext_, kRxA, (L * L / 12.0) * p);
  put_block(f_ext_, kRB, 0.5 * L * p);
  put_block(f_ext_, kRxB, (-L * L / 12.0) * p);

  // M = ∫ ρA S_cᵀS_c + ρI_z S_yᵀS_y + ρI_y S_zᵀS_z dx: products of cubics (degree 6) are
  // integrated exactly by 4 Gauss points. Assembled as 8×8 block coefficients ⊗ I₃.
  std::array<std::array<double, kBlocks>, kBlocks> m{};
  constexpr int n_mass = 4;
  for (int g = 0; g < n_mass; ++g) {
    const double xi = 0.5 * (1.0 + gauss_points(n_mass)[g]);
    const double w = 0.5 * L * gauss_weights(n_mass)[g];
    const HermiteAt h = hermite_at(xi * L, L);
    const int c_blocks[4] = {kRA, kRxA, kRB, kRxB};
    const double lin[2] = {1.0 - xi, xi};
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        m[c_blocks[a]][c_blocks[b]] += w * section.mass_per_length * h.s[a] * h.s[b];
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) {
        m[kRyA + 4 * a][kRyA + 4 * b] += w * section.rho_Iz * lin[a] * lin[b];
        m[kRzA + 4 * a][kRzA + 4 * b] += w * section.rho_Iy * lin[a] * lin[b];
      }
  }
  mass_.fill(0.0);
  for (int I = 0; I < kBlocks; ++I)
    for (int J = 0; J < kBlocks; ++J)
      for (int c = 0; c < 3; ++c) mass_[(3 * I + c) * kDofs + 3 * J + c] = m[I][J];
}

void AncfBeam::evaluate(const LocalState& s, Request r, LocalOutput out) const {
  CATENA_ASSERT(s.q.size() == kDofs, "AncfBeam::evaluate: q has 24 entries");
  CATENA_ASSERT(s.v.empty() || s.v.size() == kDofs, "AncfBeam::evaluate: v empty or 24");
  const double* q = s.q.data();
  const double* v = s.v.empty() ? nullptr : s.v.data();
  const double tau = section_.damping_time;

  Accumulator acc{r};
  for_each_point([&](const auto& map, double weight, const auto& k, int first, auto group) {
    add_point(map, weight, k, e_ref_.data() + first, tau, q, v, group, acc);
  });

  if (r.force) {
    for (int i = 0; i < kDofs; ++i) out.f[i] = acc.f[i] - s.path.loads * f_ext_[i];
  }
  using RowMajor24 = Eigen::Matrix<double, kDofs, kDofs, Eigen::RowMajor>;
  if (r.stiffness) Eigen::Map<RowMajor24>(out.K) = acc.K;
  if (r.damping) Eigen::Map<RowMajor24>(out.C) = acc.C;
}

void AncfBeam::mass(double* M) const {
  for (int i = 0; i < kDofs * kDofs; ++i) M[i] = mass_[i];
}

SectionResult AncfBeam::section_result(const LocalState& s) const {
  CATENA_ASSERT(s.q.size() == kDofs, "AncfBeam::section_result: q has 24 entries");
  // The midpoint is the middle axial sample (e_ref_[1]).
  const PointMap<3> map = axial_map(0.5, length_);
  const std::array<double, 3> u = map.gather(s.q.data());
  const double eps = bs::axial_strain(u)[0] - e_ref_[1];
  double eps_dot = 0.0;
  if (!s.v.empty()) {  // ε̇ = t̂·u̇
    const std::array<double, 3> u_dot = map.gather(s.v.data());
    eps_dot = (u[0] * u_dot[0] + u[1] * u_dot[1] + u[2] * u_dot[2]) /
              std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  }
  SectionResult r;
  r.axial_force = section_.EA * (eps + section_.damping_time * eps_dot);
  r.axial_strain = eps;
  // Bending couple at ξ: EI_y (κ_y − κ_y,ref) ê_y + EI_z (κ_z − κ_z,ref) ê_z, divided by
  // the stretch under the deformed-length law (the couple conjugate to the turn per
  // reference length, as for the cable). Elastic part only.
  const BendingGroup bending{section_.curvature == CurvatureMeasure::deformed_length};
  Vec3 tangent = Vec3::UnitX();
  double stretch = 1.0, stretch_coupling = 0.0;
  const auto moment_at = [&](double xi) {
    const PointMap<12> m = bending_map(xi, length_);
    const std::array<double, 12> x = m.gather(s.q.data());
    const std::array<double, 2> k = bending(x), k_ref = bending(m.gather(q_ref_.data()));
    const bs::V3<double> uv = bs::block(x, 0);
    const bs::BendingFrame<double> f = bs::bending_frame(uv, bs::block(x, 6), bs::block(x, 9));
    const Vec3 t(f.t[0], f.t[1], f.t[2]), a(f.a[0], f.a[1], f.a[2]);
    const Vec3 e_y = f.inv_a_perp * (a - a.dot(t) * t), e_z = t.cross(e_y);
    tangent = t;
    stretch = std::sqrt(bs::dot(uv, uv));
    // Deformed-length law: κ_i ∝ 1/λ at a fixed turn, so ∂W/∂λ adds −Σ EI_i (κ_i − κ_i,ref)
    // κ_i/λ to EA ε; the tangential force is EA ε less it (as the cable's).
    stretch_coupling =
        (section_.EI_y * (k[0] - k_ref[0]) * k[0] + section_.EI_z * (k[1] - k_ref[1]) * k[1]) /
        stretch;
    const double scale = bending.per_deformed_length ? 1.0 / stretch : 1.0;
    return Vec3(scale * (section_.EI_y * (k[0] - k_ref[0]) * e_y +
                         section_.EI_z * (k[1] - k_ref[1]) * e_z));
  };
  // Shear from the moment's balance, n⊥ = t × dM/ds / λ, by central differences about the
  // mid-point (as the cable's); evaluated first so that tangent and stretch are the
  // mid-point's.
  constexpr double h = 0.25;
  const Vec3 dM = (moment_at(0.5 + h) - moment_at(0.5 - h)) / (2.0 * h * length_);
  r.bending_moment = moment_at(0.5);
  r.shear_force = tangent.cross(dM) / stretch;
  if (bending.per_deformed_length) r.axial_force -= stretch_coupling;
  // Torsion GJ (κ_x − κ_x,ref), constant along the element.
  const PointMap<12> twist = twist_map();
  const TwistGroup group{1.0 / length_};
  r.torsion =
      section_.GJ * (group(twist.gather(s.q.data()))[0] - group(twist.gather(q_ref_.data()))[0]);
  return r;
}

double AncfBeam::strain_energy(std::span<const double> q) const {
  CATENA_ASSERT(q.size() == kDofs, "AncfBeam::strain_energy: q has 24 entries");
  double energy = 0.0;
  for_each_point([&](const auto& map, double weight, const auto& k, int first, auto group) {
    const auto e = group(map.gather(q.data()));
    for (std::size_t i = 0; i < e.size(); ++i)
      energy += 0.5 * weight * k[i] * std::pow(e[i] - e_ref_[first + i], 2);
  });
  return energy;
}

}  // namespace catena::elements
