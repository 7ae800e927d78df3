#include "catena/couplings/slider_constraint.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "catena/core/error.hpp"
#include "catena/elements/hermite.hpp"
#include "catena/model/node_kinds.hpp"

namespace catena::couplings {

SliderConstraint::SliderConstraint(const model::Model& model, int index)
    : ConstraintCoupling(index) {
  const model::Constraint& c = model.constraints[static_cast<size_t>(index)];
  CATENA_ASSERT(c.type == model::ConstraintType::slider && c.slider >= 0,
                "SliderConstraint takes a slider");
  const model::Slider& slider = model.sliders[static_cast<size_t>(c.slider)];
  damping_ = slider.damping;
  friction_ = slider.friction;
  stick_speed_ = slider.stick_speed;
  const std::vector<int>& path = model.paths[static_cast<size_t>(slider.path)].elements;
  stations_ = model::path_stations(model, path);
  for (int k = 0; k < 3; ++k) dofs_.push_back(DofKey::multiplier(index, k));
  for (int k = 0; k < 4; ++k) dofs_.push_back(DofKey::node(slider.node, k));
  // Each path node once, ascending, with its position and slope (6 DOFs).
  const std::vector<int> counts = model::all_node_dofs(model);
  std::map<int, int> first_dof;
  for (int e : path)
    for (int node : model.elements[static_cast<size_t>(e)].nodes) first_dof[node] = 0;
  for (auto& [node, first] : first_dof) {
    CATENA_ASSERT(counts[static_cast<size_t>(node)] >= 6,
                  "a slider's path is made of cable or beam elements");
    first = static_cast<int>(dofs_.size());
    for (int k = 0; k < 6; ++k) dofs_.push_back(DofKey::node(node, k));
  }
  for (std::size_t i = 0; i < path.size(); ++i) {
    const auto& nodes = model.elements[static_cast<size_t>(path[i])].nodes;
    element_a_.push_back(first_dof[nodes.front()]);
    element_b_.push_back(first_dof[nodes.back()]);
    reversed_.push_back(model::element_reversed(model, path, i) ? 1 : 0);
  }
}

void SliderConstraint::pattern(std::vector<std::pair<int, int>>& entries) const {
  // λ, r and s with each other and with every path DOF (the path's own block is its
  // elements').
  entries.clear();
  const int n = static_cast<int>(dofs_.size());
  for (int i = 0; i < kPath; ++i)
    for (int j = 0; j < n; ++j) {
      entries.emplace_back(i, j);
      if (j >= kPath) entries.emplace_back(j, i);
    }
}

std::size_t SliderConstraint::element_holding(double s) const {
  return stations_.element_at(std::clamp(s, 0.0, stations_.length()));
}

SliderConstraint::Place SliderConstraint::place(double s) const {
  Place p;
  const double on_path = std::clamp(s, 0.0, stations_.length());
  p.element = element_holding(s);
  const double L = stations_.element_length(p.element);
  const double u = on_path - stations_.start[p.element];
  const bool back = reversed_[p.element] != 0;
  p.sigma = back ? -1.0 : 1.0;
  const elements::HermiteAt h = elements::hermite_at(back ? L - u : u, L);
  // Beyond an end the path goes on along its end tangent: r(end) + (s − end) t(end), so that
  // a Newton iterate that overshoots sees a straight line, not the end cubic's growth (a
  // converged state there has left the path: solvers/time/state_guard.hpp).
  const double beyond = s - on_path;
  for (int b = 0; b < 4; ++b) {
    p.S[b] = h.s[b] + beyond * p.sigma * h.ds[b];
    p.dS[b] = h.ds[b];
    p.ddS[b] = beyond != 0.0 ? 0.0 : h.dds[b];
  }
  return p;
}

void SliderConstraint::active_dofs_at(double, const DofValues& q,
                                      std::vector<int>& positions) const {
  const std::size_t element = element_holding(q.at(kSlide));
  positions.clear();
  for (int k = 0; k < kPath; ++k) positions.push_back(k);
  for (const int first : {element_a_[element], element_b_[element]})
    for (int k = 0; k < 6; ++k) positions.push_back(first + k);
}

void SliderConstraint::evaluate(const CouplingState& s, double* f, std::span<const MatrixRequest> m,
                                Scratch&) const {
  const int n = static_cast<int>(s.q.size());
  CATENA_ASSERT(n == kPath + 12, "a slider acts on lambda, r, s and one path element");
  const std::span<const double> q = s.q;
  const Place p = place(q[kSlide]);
  auto block = [&](int b) {
    const int i = kFirst[b];
    return Vec3(q[static_cast<size_t>(i)], q[static_cast<size_t>(i + 1)],
                q[static_cast<size_t>(i + 2)]);
  };
  Vec3 r_path = Vec3::Zero(), tangent = Vec3::Zero(), curvature = Vec3::Zero();
  for (int b = 0; b < 4; ++b) {
    const Vec3 qb = block(b);
    r_path += p.S[b] * qb;
    tangent += p.sigma * p.dS[b] * qb;
    curvature += p.ddS[b] * qb;
  }
  const Vec3 lambda(q[kLambda], q[kLambda + 1], q[kLambda + 2]);
  const Vec3 point(q[kPoint], q[kPoint + 1], q[kPoint + 2]);
  const double slide_rate = s.v.empty() ? 0.0 : s.v[kSlide];
  // Coulomb friction F = μ n φ(ṡ) on the s row (slider_constraint.hpp), n = |t × λ|; its
  // derivatives in n are zero where n is (no normal force: no friction, a kink).
  const double normal = friction_ > 0.0 ? tangent.cross(lambda).norm() : 0.0;
  const double root = std::sqrt(slide_rate * slide_rate + stick_speed_ * stick_speed_);
  const double phi = slide_rate / root;
  const double dphi = stick_speed_ * stick_speed_ / (root * root * root);
  Vec3 dn_dlambda = Vec3::Zero(), dn_dtangent = Vec3::Zero();
  if (normal > 0.0) {
    const double tl = tangent.dot(lambda);
    dn_dlambda = (tangent.squaredNorm() * lambda - tl * tangent) / normal;
    dn_dtangent = (lambda.squaredNorm() * tangent - tl * lambda) / normal;
  }
  if (f) {
    std::fill(f, f + n, 0.0);
    for (int d = 0; d < 3; ++d) {
      f[kLambda + d] = point[d] - r_path[d];
      f[kPoint + d] = lambda[d];
    }
    f[kSlide] = -tangent.dot(lambda) + damping_ * slide_rate + friction_ * normal * phi;
    for (int b = 0; b < 4; ++b)
      for (int d = 0; d < 3; ++d) f[kFirst[b] + d] += -p.S[b] * lambda[d];
  }
  for (const MatrixRequest& r : m) {
    double* J = r.out;
    std::fill(J, J + static_cast<size_t>(n) * static_cast<size_t>(n), 0.0);
    const JacobianCoefficients& c = r.c;
    auto add = [&](int i, int j, double value) { J[static_cast<size_t>(i) * n + j] += value; };
    // Gᵀ (nodal rows, multiplier columns) and G (multiplier rows, nodal columns).
    for (int d = 0; d < 3; ++d) {
      add(kPoint + d, kLambda + d, c.c_lambda);
      add(kLambda + d, kPoint + d, c.c_g);
      add(kSlide, kLambda + d, c.c_lambda * (-tangent[d] + friction_ * phi * dn_dlambda[d]));
      add(kLambda + d, kSlide, -c.c_g * tangent[d]);
      for (int b = 0; b < 4; ++b) {
        add(kFirst[b] + d, kLambda + d, -c.c_lambda * p.S[b]);
        add(kLambda + d, kFirst[b] + d, -c.c_g * p.S[b]);
      }
    }
    // ∂(Gᵀλ)/∂q: the s row's −t·λ varies with s and with the path's blocks.
    // The friction's, through t = σ Σ S_b' q_b (∂t/∂s = κ), in the s row only.
    if (c.c_K != 0.0) {
      const double mu_phi = friction_ * phi;
      add(kSlide, kSlide, c.c_K * (-curvature.dot(lambda) + mu_phi * dn_dtangent.dot(curvature)));
      for (int b = 0; b < 4; ++b)
        for (int d = 0; d < 3; ++d) {
          const double h = -c.c_K * p.sigma * p.dS[b] * lambda[d];
          add(kSlide, kFirst[b] + d, h + c.c_K * mu_phi * p.sigma * p.dS[b] * dn_dtangent[d]);
          add(kFirst[b] + d, kSlide, h);
        }
    }
    if (c.c_C != 0.0) add(kSlide, kSlide, c.c_C * (damping_ + friction_ * normal * dphi));
  }
}

void SliderConstraint::acceleration_target(const CouplingState& s, std::span<double> out) const {
  const std::span<const double> q = s.q;
  const Place p = place(q[kSlide]);
  std::fill(out.begin(), out.end(), 0.0);
  if (s.v.empty()) return;
  const double rate = s.v[kSlide];
  Vec3 tangent_rate = Vec3::Zero(), curvature = Vec3::Zero();
  for (int b = 0; b < 4; ++b) {
    const int i = kFirst[b];
    for (int d = 0; d < 3; ++d) {
      tangent_rate[d] += p.sigma * p.dS[b] * s.v[static_cast<size_t>(i + d)];
      curvature[d] += p.ddS[b] * q[static_cast<size_t>(i + d)];
    }
  }
  // g = r − r_path(s): d²g/dt² = G a − (2 ṡ ṫ + ṡ² κ), so G a = γ = 2 ṡ ṫ + ṡ² κ.
  for (int d = 0; d < 3; ++d)
    out[static_cast<size_t>(d)] = 2.0 * rate * tangent_rate[d] + rate * rate * curvature[d];
}

}  // namespace catena::couplings
