#include "catena/elements/ancf_cable.hpp"

#include "catena/core/error.hpp"
#include "catena/elements/hermite.hpp"

#include <algorithm>
#include <cmath>

namespace catena::elements {
namespace {

// Axial strain sampled at the Lobatto 3 points (x = 0, L/2, L; Simpson weights): Gauss
// sampling locks in bending-dominated states of slender cables (membrane locking; the
// error grows with EA·L²/EI), while two Gauss points would leave a zero-energy stretching
// mode. Bending at 3 Gauss points: κ² is nearly quadratic in x for moderate stretch.
constexpr double kAxialPoints[3] = {0.0, 0.5, 1.0};
constexpr double kAxialWeights[3] = {1.0 / 6.0, 4.0 / 6.0, 1.0 / 6.0};
constexpr int kBendingPoints = 3;

// Bending energy density per unit of the stiffness factor (see evaluate), as a function of
// g = u·u, p = w·w, c = u·w, with its derivatives. Both laws are linear in p with no p·c
// term, so F_pp = F_pc = 0.
struct BendingDensity {
  double F, Fg, Fp, Fc, Fgg, Fgp, Fgc, Fcc;
};

// Per reference length: κ₀²/a² = |u×w|²/g² = p/g − c²/g².
BendingDensity reference_length_density(double g, double p, double c) {
  const double ig = 1.0 / g, ig2 = ig * ig, ig3 = ig2 * ig, ig4 = ig3 * ig;
  return {p * ig - c * c * ig2,
          -p * ig2 + 2.0 * c * c * ig3,
          ig,
          -2.0 * c * ig2,
          2.0 * p * ig3 - 6.0 * c * c * ig4,
          -ig2,
          4.0 * c * ig3,
          -2.0 * ig2};
}

// Per deformed length: κ² = |u×w|²/g³ = p/g² − c²/g³.
BendingDensity deformed_length_density(double g, double p, double c) {
  const double ig = 1.0 / g, ig2 = ig * ig, ig3 = ig2 * ig, ig4 = ig3 * ig, ig5 = ig4 * ig;
  return {p * ig2 - c * c * ig3,
          -2.0 * p * ig3 + 3.0 * c * c * ig4,
          ig2,
          -2.0 * c * ig3,
          6.0 * p * ig4 - 12.0 * c * c * ig5,
          -2.0 * ig3,
          6.0 * c * ig4,
          -2.0 * ig3};
}

using Blocks = std::array<Vec3, 4>;

// The axial law per unit EA, of the element's mean strain ε̄ (see evaluate): G(ε̄), with
// damping τ W(ε̄) ε̇. Linear (G = ε, W = 1), or
// tension-only: G = (1 − r) m(ε) + r ε with m a C¹ smoothed max(ε, 0) (quadratic
// (ε + δ)²/(4δ) for |ε| < δ) and r = kSlackStiffness, W = m'(ε), so that damping fades with
// the tension. The smoothing gives the law a tangent everywhere and moves N by at most
// EA·δ/4; on its own (with a switch per sampling point) it did not stop the Newton
// failures of slackening cable droppers, the switch on the mean strain did (measured:
// docs/catenary.md, "Droppers as cables").
struct AxialLaw {
  struct At {
    double G, dG, W, dW;
  };
  bool tension_only;

  explicit AxialLaw(bool tension_only_) : tension_only(tension_only_) {}

  At at(double eps) const {
    if (!tension_only) return {eps, 1.0, 1.0, 0.0};
    constexpr double d = AncfCable::kSlackBand;
    constexpr double r = AncfCable::kSlackStiffness;
    double m = 0.0, dm = 0.0, ddm = 0.0;
    if (eps >= d) {
      m = eps;
      dm = 1.0;
    } else if (eps > -d) {
      m = (eps + d) * (eps + d) / (4.0 * d);
      dm = (eps + d) / (2.0 * d);
      ddm = 1.0 / (2.0 * d);
    }
    return {(1.0 - r) * m + r * eps, (1.0 - r) * dm + r, dm, ddm};
  }
};

// r' (or ṙ') at a point: Σ S'_i x_i over the Hermite blocks.
Vec3 slope_at(const HermiteAt& h, const Blocks& x) {
  Vec3 u = Vec3::Zero();
  for (int i = 0; i < 4; ++i) u += h.ds[i] * x[i];
  return u;
}

Blocks gather(std::span<const double> x) {
  Blocks b;
  for (int i = 0; i < 4; ++i) b[i] = Vec3(x[3 * i], x[3 * i + 1], x[3 * i + 2]);
  return b;
}

// Generalised force and tangent at one quadrature point in terms of (u, w). The tangent
// blocks are set only when a tangent is requested: a residual evaluation (force only, most
// of a dynamic run's element calls) neither forms nor clears them.
struct PointTangent {
  Vec3 fu = Vec3::Zero(), fw = Vec3::Zero();  // ∂φ/∂u, ∂φ/∂w (+ damping force on u)
  Mat3 Huu, Huw, Hwu, Hww;                    // uninitialised unless Request::stiffness
  Mat3 Cuu;                                   // ∂(damping force)/∂u̇, Request::damping only
};

}  // namespace

AncfCable::AncfCable(double length, const CableSection& section, const Vec3& gravity,
                     const Vec3& distributed_load)
    : length_(length),
      section_(section),
      // Mass per mesh length: the unstretched length L/(1+ε_p) carries μ per unit length.
      load_(section.mass_per_length / (1.0 + section.prestrain) * gravity + distributed_load) {
  CATENA_ASSERT(length > 0.0, "AncfCable: length must be positive");
}

void AncfCable::evaluate(const LocalState& s, Request r, LocalOutput out) const {
  const double L = length_;
  const double a = 1.0 + section_prestrain(section_, s.path);
  const double EA = section_.EA, tau = section_.damping_time;
  // Bending energy per mesh length: ½ kb F(g, p, c) (ancf_cable.hpp).
  const bool per_reference_length = section_.curvature == CurvatureMeasure::reference_length;
  const double kb = per_reference_length ? section_.EI * a : section_.EI / a;
  const bool damped = tau > 0.0 && !s.v.empty();
  const Blocks e = gather(s.q);
  Blocks ev;
  if (damped) ev = gather(s.v);

  Blocks f;
  for (auto& b : f) b.setZero();
  std::array<std::array<Mat3, 4>, 4> K{}, C{};
  if (r.stiffness)
    for (auto& row : K)
      for (auto& b : row) b.setZero();
  if (r.damping)
    for (auto& row : C)
      for (auto& b : row) b.setZero();

  const Mat3 I = Mat3::Identity();
  // Adds a point's generalised force and tangent (in terms of u = r', w = r'') to the
  // element blocks: f_i += W (S'_i f_u + S''_i f_w), K_ij += W [S'_j (S'_i H_uu + S''_i H_wu)
  // + S''_j (S'_i H_uw + S''_i H_ww)], C_ij += W S'_i S'_j C_uu.
  auto accumulate = [&](const HermiteAt& h, double W, const PointTangent& pt, bool bending) {
    for (int i = 0; i < 4; ++i) {
      f[i] += W * h.ds[i] * pt.fu;
      if (bending) f[i] += W * h.dds[i] * pt.fw;
    }
    if (!r.stiffness && !r.damping) return;
    if (r.stiffness) {
      for (int i = 0; i < 4; ++i) {
        Mat3 A = W * h.ds[i] * pt.Huu;
        if (bending) A += W * h.dds[i] * pt.Hwu;
        for (int j = 0; j < 4; ++j) K[i][j] += h.ds[j] * A;
        if (bending) {
          const Mat3 B = W * (h.ds[i] * pt.Huw + h.dds[i] * pt.Hww);
          for (int j = 0; j < 4; ++j) K[i][j] += h.dds[j] * B;
        }
      }
    }
    if (r.damping && tau > 0.0 && !bending)  // the axial points' dashpot only
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) C[i][j] += (W * h.ds[i] * h.ds[j]) * pt.Cuu;
  };

  // Axial strain and its rate (Kelvin–Voigt) at the Lobatto points: ε_k = a|u_k| − 1.
  // Linear section: N_k = EA (ε_k + τ ε̇_k). Tension-only section (AxialLaw): the switch
  // acts on the element's mean strain ε̄ = Σ w_k ε_k (Simpson's rule for its arc-length
  // strain), the strain's variation about the mean stays elastic:
  //   energy / (L EA/a) = Φ(ε̄) + ½ Σ w_k (ε_k − ε̄)²,  Φ' = G,
  //   N_k = EA (G(ε̄) + ε_k − ε̄ + τ W(ε̄) ε̇_k),
  // which is N_k = EA ε_k wherever G(ε̄) = ε̄ (taut, or a linear section). A switch per
  // sampling point would leave a slack element's end slopes, whose strain points sit at
  // the nodes, with no stiffness along them and almost no inertia: they flapped, and
  // Newton cycled between the points' states (docs/catenary.md, "Droppers as cables").
  // In terms of b = Σ_k w_k S'_k ⊗ t_k (∂ε̄/∂e = a b) and v = Σ_k w_k ε̇_k S'_k ⊗ t_k,
  //   K = Σ_k (per point: t_k (∂N_k/∂u_k)ᵀ + N_k ∂t_k/∂u_k)
  //       + L EA a [(G'(ε̄) − 1) b bᵀ + τ W'(ε̄) v bᵀ],
  // with ∂N_k/∂u_k = EA a (t_k + τ W (∂t_k/∂u_k) u̇_k) and ∂t/∂u = (I − t tᵀ)/|u|.
  const AxialLaw law(section_.tension_only);
  struct AxialPoint {
    HermiteAt h;
    Vec3 t, u_rate;
    Mat3 P;
    double eps, eps_rate;
  };
  std::array<AxialPoint, 3> pts;
  double eps_mean = 0.0;
  for (int k = 0; k < 3; ++k) {
    AxialPoint& p = pts[k];
    p.h = hermite_at(kAxialPoints[k] * L, L);
    const Vec3 u = slope_at(p.h, e);
    const double norm_u = u.norm();
    p.t = u / norm_u;
    p.eps = a * norm_u - 1.0;
    // ∂t/∂u: the tangent needs it, the force does not.
    if (r.stiffness) p.P = (I - p.t * p.t.transpose()) / norm_u;
    p.u_rate = damped ? slope_at(p.h, ev) : Vec3::Zero();
    p.eps_rate = a * p.t.dot(p.u_rate);
    eps_mean += kAxialWeights[k] * p.eps;
  }
  const AxialLaw::At law_at = law.at(eps_mean);
  // G(ε̄) − ε̄: exactly 0 for a linear section, whose N_k is then EA ε_k to the last bit.
  const double offset = law_at.G - eps_mean;
  const bool rank_one = r.stiffness && section_.tension_only;
  Blocks b, v;
  for (int i = 0; i < 4; ++i) b[i] = v[i] = Vec3::Zero();
  for (int k = 0; k < 3; ++k) {
    const AxialPoint& p = pts[k];
    const double N = EA * (p.eps + offset + tau * law_at.W * p.eps_rate);
    PointTangent pt;
    pt.fu = N * p.t;
    if (r.stiffness) {
      Vec3 dN = EA * a * p.t;
      if (damped) dN += EA * tau * law_at.W * a * (p.P * p.u_rate);
      pt.Huu = p.t * dN.transpose() + N * p.P;
    }
    if (rank_one)
      for (int i = 0; i < 4; ++i) {
        b[i] += kAxialWeights[k] * p.h.ds[i] * p.t;
        v[i] += kAxialWeights[k] * p.eps_rate * p.h.ds[i] * p.t;
      }
    if (r.damping && tau > 0.0) pt.Cuu = EA * tau * law_at.W * a * p.t * p.t.transpose();
    accumulate(p.h, kAxialWeights[k] * L, pt, false);
  }
  if (rank_one) {
    const double cb = L * EA * a * (law_at.dG - 1.0),
                 cv = damped ? L * EA * a * tau * law_at.dW : 0.0;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) K[i][j] += (cb * b[i] + cv * v[i]) * b[j].transpose();
  }

  // Bending: ½ kb F(g, p, c).
  const auto xg = gauss_points(kBendingPoints);
  const auto wg = gauss_weights(kBendingPoints);
  for (int k = 0; k < kBendingPoints; ++k) {
    const HermiteAt h = hermite_at(0.5 * (1.0 + xg[k]) * L, L);
    Vec3 u = Vec3::Zero(), w = Vec3::Zero();
    for (int i = 0; i < 4; ++i) {
      u += h.ds[i] * e[i];
      w += h.dds[i] * e[i];
    }
    const double g = u.squaredNorm(), p = w.squaredNorm(), c = u.dot(w);
    const BendingDensity F =
        per_reference_length ? reference_length_density(g, p, c) : deformed_length_density(g, p, c);
    PointTangent pt;
    pt.fu = 0.5 * kb * (2.0 * F.Fg * u + F.Fc * w);
    pt.fw = 0.5 * kb * (2.0 * F.Fp * w + F.Fc * u);
    if (r.stiffness) {
      const Vec3 Gu = 2.0 * u;  // ∇_u g ; ∇_w p = 2w ; ∇_u c = w, ∇_w c = u
      pt.Huu = 0.5 * kb *
               (F.Fgg * Gu * Gu.transpose() + F.Fgc * (Gu * w.transpose() + w * Gu.transpose()) +
                F.Fcc * w * w.transpose() + 2.0 * F.Fg * I);
      pt.Huw = 0.5 * kb *
               (F.Fgp * Gu * (2.0 * w).transpose() + F.Fgc * Gu * u.transpose() +
                F.Fcc * w * u.transpose() + F.Fc * I);
      pt.Hwu = pt.Huw.transpose();
      pt.Hww = 0.5 * kb * (F.Fcc * u * u.transpose() + 2.0 * F.Fp * I);
    }
    accumulate(h, 0.5 * wg[k] * L, pt, true);
  }

  if (r.force) {
    // ∫ Sᵀ (μ_x g + q) dx per Hermite block: ∫_0^L S_i dx = L/2, L²/12, L/2, −L²/12.
    const double integral[4] = {L / 2, L * L / 12, L / 2, -L * L / 12};
    for (int i = 0; i < 4; ++i) {
      const Vec3 fi = f[i] - s.path.loads * (integral[i] * load_);
      for (int d = 0; d < 3; ++d) out.f[3 * i + d] = fi[d];
    }
  }
  auto scatter = [](const std::array<std::array<Mat3, 4>, 4>& blocks, double* dst) {
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        for (int a2 = 0; a2 < 3; ++a2)
          for (int b2 = 0; b2 < 3; ++b2) dst[(3 * i + a2) * 12 + 3 * j + b2] = blocks[i][j](a2, b2);
  };
  if (r.stiffness) scatter(K, out.K);
  if (r.damping) scatter(C, out.C);
}

void AncfCable::mass(double* M) const {
  // Consistent mass: μ_x ∫ S_i S_j dx ⊗ I3, the classical cubic Hermite matrix (L/420)·[…].
  const double L = length_;
  const double mu_mesh = section_.mass_per_length / (1.0 + section_.prestrain);
  const double m[4][4] = {{156, 22 * L, 54, -13 * L},
                          {22 * L, 4 * L * L, 13 * L, -3 * L * L},
                          {54, 13 * L, 156, -22 * L},
                          {-13 * L, -3 * L * L, -22 * L, 4 * L * L}};
  for (int k = 0; k < 144; ++k) M[k] = 0.0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int d = 0; d < 3; ++d) M[(3 * i + d) * 12 + 3 * j + d] = mu_mesh * L / 420.0 * m[i][j];
}

double AncfCable::path_prestrain(double prestrain, const LoadPath& path) {
  const double held = std::max(prestrain, kPathPrestrain);
  return held * path.prestrain + path.release * (prestrain - held);
}

double AncfCable::section_prestrain(const CableSection& section, const LoadPath& path) {
  return section.prestrain_with_loads ? section.prestrain * path.loads
                                      : path_prestrain(section.prestrain, path);
}

SectionResult AncfCable::section_result(const LocalState& s) const {
  // Axial: a linear section reports its mid-point force EA ε_mid (at rest). A
  // tension-only one reports the force its switch acts on, EA G(ε̄), and the mean strain
  // ε̄: a dropper's one tension per element, the slack residue kSlackStiffness·EA·ε̄ < 0
  // when it is slack. Under the deformed-length law the tangential section force is
  // EA ε − EI κ²/λ (docs/formulation.md, "Bending law").
  const Blocks e = gather(s.q);
  const double L = length_, a = 1.0 + section_prestrain(section_, s.path);
  double eps[3], eps_mean = 0.0;
  for (int k = 0; k < 3; ++k) {
    eps[k] = a * slope_at(hermite_at(kAxialPoints[k] * L, L), e).norm() - 1.0;
    eps_mean += kAxialWeights[k] * eps[k];
  }
  SectionResult r;
  if (section_.tension_only) {
    r.axial_force = section_.EA * AxialLaw(true).at(eps_mean).G;
    r.axial_strain = eps_mean;
  } else {
    r.axial_force = section_.EA * eps[1];
    r.axial_strain = eps[1];
  }
  // Bending: the couple conjugate to the tangent's turn per unstretched length, κ₀ =
  // a (u × w)/|u|² as a vector (binormal): M = EI κ₀, or EI κ₀/λ² under the
  // deformed-length law (energy ½EI κ₀²/λ², λ = a|u| the stretch).
  const bool deformed = section_.curvature == CurvatureMeasure::deformed_length;
  const auto moment_at = [&](double xi, Vec3* tangent, double* stretch) {
    const HermiteAt h = hermite_at(xi * L, L);
    Vec3 u = Vec3::Zero(), w = Vec3::Zero();
    for (int i = 0; i < 4; ++i) {
      u += h.ds[i] * e[i];
      w += h.dds[i] * e[i];
    }
    const double lambda = a * u.norm();
    if (tangent) *tangent = u.normalized();
    if (stretch) *stretch = lambda;
    const Vec3 kappa0 = a * u.cross(w) / u.squaredNorm();
    return Vec3(section_.EI * kappa0 / (deformed ? lambda * lambda : 1.0));
  };
  Vec3 t;
  double lambda = 1.0;
  r.bending_moment = moment_at(0.5, &t, &lambda);
  if (deformed && !section_.tension_only) {
    const double kappa = r.bending_moment.norm() * lambda / section_.EI;  // |u×w|/|u|³
    r.axial_force -= section_.EI * kappa * kappa / lambda;
  }
  // Shear from the moment's balance, dM/ds₀ + λ t × n = 0: n⊥ = t × dM/ds₀ / λ, with
  // dM/ds₀ = a dM/dx by central differences about the mid-point (exact for the linear
  // moment of a cubic element's small deflection).
  constexpr double h = 0.25;
  const Vec3 dM = a *
                  (moment_at(0.5 + h, nullptr, nullptr) - moment_at(0.5 - h, nullptr, nullptr)) /
                  (2.0 * h * L);
  r.shear_force = t.cross(dM) / lambda;
  return r;
}

}  // namespace catena::elements
