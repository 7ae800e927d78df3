#include "catena/couplings/joint_spring.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "catena/core/error.hpp"
#include "catena/couplings/joint_constraint.hpp"
#include "catena/elements/dual.hpp"

namespace catena::couplings {
namespace {

constexpr int kMaxVariables = 24;
using D = elements::Dual2<kMaxVariables>;
using D3 = std::array<D, 3>;

D dot(const D3& a, const D3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
D3 cross(const D3& a, const D3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
D3 constant(const Vec3& v) { return {D(v[0]), D(v[1]), D(v[2])}; }

// Body coordinates of a global vector in a body's reference frame.
Vec3 in_body(const model::Node& node, const Vec3& v) {
  return {node.tangent.dot(v), node.section_y.dot(v), node.section_z.dot(v)};
}

}  // namespace

JointSpring::JointSpring(const model::Model& model, int joint_index) {
  const model::Joint& joint = model.joints[static_cast<size_t>(joint_index)];
  CATENA_ASSERT(
      joint.type == model::JointType::revolute || joint.type == model::JointType::prismatic,
      "JointSpring: a revolute or prismatic joint");
  type_ = joint.type;
  stiffness_ = joint.stiffness;
  damping_ = joint.damping;
  neutral_ = joint.neutral;
  actuator_ = joint.actuator;
  neutral_velocity_ = joint.neutral_velocity;
  neutral_amplitude_ = joint.neutral_amplitude;
  neutral_frequency_ = joint.neutral_frequency;
  limit_ = joint.limit;
  friction_ = joint.friction;
  stick_speed_ = joint.stick_speed;
  const Vec3 u = joint.axis.normalized(), n1 = JointConstraint::normal(u);
  const int node_a = model.rigid_bodies[static_cast<size_t>(joint.body_a)].node;
  const model::Node& a = model.nodes[static_cast<size_t>(node_a)];
  point_a_ = in_body(a, joint.point - a.position);
  n1_a_ = in_body(a, n1);
  for (int k = 0; k < 12; ++k) dofs_.push_back(DofKey::node(node_a, k));
  to_ground_ = joint.body_b < 0;
  if (to_ground_) {
    ground_point_ = joint.point;
    ground_axis_ = u;
    ground_n1_ = n1;
  } else {
    const int node_b = model.rigid_bodies[static_cast<size_t>(joint.body_b)].node;
    const model::Node& b = model.nodes[static_cast<size_t>(node_b)];
    point_b_ = in_body(b, joint.point - b.position);
    axis_b_ = in_body(b, u);
    n1_b_ = in_body(b, n1);
    for (int k = 0; k < 12; ++k) dofs_.push_back(DofKey::node(node_b, k));
    n_ = 24;
  }
}

double JointSpring::coordinate(std::span<const double> q) const {
  // The same expressions as evaluate's, in doubles.
  auto axis_of = [&](int first, const Vec3& c) -> Vec3 {
    Vec3 d = Vec3::Zero();
    for (int k = 0; k < 3; ++k)
      d += c[k] * Vec3(q[first + 3 + 3 * k], q[first + 4 + 3 * k], q[first + 5 + 3 * k]);
    return d;
  };
  auto point_of = [&](int first, const Vec3& xi) -> Vec3 {
    return Vec3(q[first], q[first + 1], q[first + 2]) + axis_of(first, xi);
  };
  const Vec3 u_b = to_ground_ ? ground_axis_ : axis_of(12, axis_b_);
  if (type_ == model::JointType::prismatic) {
    const Vec3 p_b = to_ground_ ? ground_point_ : point_of(12, point_b_);
    return (point_of(0, point_a_) - p_b).dot(u_b);
  }
  const Vec3 n1_a = axis_of(0, n1_a_), n1_b = to_ground_ ? ground_n1_ : axis_of(12, n1_b_);
  return std::atan2(n1_b.cross(n1_a).dot(u_b), n1_a.dot(n1_b));
}

void JointSpring::evaluate(const CouplingState& s, double* f, std::span<const MatrixRequest> m,
                           Scratch&) const {
  // No mass: a request for M (or Gᵀ, G) alone gets zeros, without evaluating ξ — it may come
  // at a state that is no configuration (the mass matrix is assembled at q = 0, where the
  // angle is undefined).
  const bool needed = f || std::any_of(m.begin(), m.end(), [](const MatrixRequest& r) {
                        return r.c.c_K != 0.0 || r.c.c_C != 0.0;
                      });
  if (!needed) {
    for (const MatrixRequest& r : m) std::fill(r.out, r.out + n_ * n_, 0.0);
    return;
  }
  std::array<D, kMaxVariables> x{};
  for (int j = 0; j < n_; ++j) x[static_cast<size_t>(j)] = D::variable(s.q[j], j);
  auto axis_of = [&](int first, const Vec3& c) {
    D3 d{D(0.0), D(0.0), D(0.0)};
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 3; ++i)
        d[static_cast<size_t>(i)] =
            d[static_cast<size_t>(i)] + c[k] * x[static_cast<size_t>(first + 3 + 3 * k + i)];
    return d;
  };
  auto point_of = [&](int first, const Vec3& xi) {
    D3 p = axis_of(first, xi);
    for (int i = 0; i < 3; ++i)
      p[static_cast<size_t>(i)] = p[static_cast<size_t>(i)] + x[static_cast<size_t>(first + i)];
    return p;
  };
  const D3 u_b = to_ground_ ? constant(ground_axis_) : axis_of(12, axis_b_);
  D xi;
  if (type_ == model::JointType::prismatic) {
    const D3 p_a = point_of(0, point_a_);
    const D3 p_b = to_ground_ ? constant(ground_point_) : point_of(12, point_b_);
    xi = dot(D3{p_a[0] - p_b[0], p_a[1] - p_b[1], p_a[2] - p_b[2]}, u_b);
  } else {
    const D3 n1_a = axis_of(0, n1_a_);
    const D3 n1_b = to_ground_ ? constant(ground_n1_) : axis_of(12, n1_b_);
    xi = atan2(dot(cross(n1_b, n1_a), u_b), dot(n1_a, n1_b));
  }
  double rate = 0.0;  // ξ̇ = ∂ξ/∂q · v
  if (!s.v.empty())
    for (int j = 0; j < n_; ++j) rate += xi.grad(j) * s.v[j];
  // The neutral at t and its rate.
  const double omega = 2.0 * M_PI * neutral_frequency_;
  const double neutral =
      neutral_ + neutral_velocity_ * s.t + neutral_amplitude_ * std::sin(omega * s.t);
  const double neutral_rate =
      neutral_velocity_ + neutral_amplitude_ * omega * std::cos(omega * s.t);
  // The angle is the principal one, in (−π, π], while a moving neutral runs on: the spring
  // acts on their difference taken the short way round (a servo turning a body on and on
  // follows its target through ±π). The derivatives do not change.
  double offset = xi.value() - neutral;
  if (type_ == model::JointType::revolute) offset = std::remainder(offset, 2.0 * M_PI);
  const double u = stiffness_ * offset + damping_ * (rate - neutral_rate) - actuator_;
  // The limit: P = L tanh(u/L), P' = 1 − tanh².
  double capped = u, slope = 1.0;
  if (limit_ > 0.0) {
    const double th = std::tanh(u / limit_);
    capped = limit_ * th;
    slope = 1.0 - th * th;
  }
  // Dry friction, regularised: g = μ ξ̇/√(ξ̇² + w²), g' = μ w²/(ξ̇² + w²)^{3/2}.
  double friction = 0.0, friction_slope = 0.0;
  if (friction_ > 0.0) {
    const double r = std::sqrt(rate * rate + stick_speed_ * stick_speed_);
    friction = friction_ * rate / r;
    friction_slope = friction_ * stick_speed_ * stick_speed_ / (r * r * r);
  }
  const double force = capped + friction;
  const double k_t = slope * stiffness_, c_t = slope * damping_ + friction_slope;
  if (f)
    for (int j = 0; j < n_; ++j) f[j] = force * xi.grad(j);
  if (m.empty()) return;
  // ∂²ξ/∂q² v, for the dashpot's part of K.
  std::array<double, kMaxVariables> hv{};
  if (!s.v.empty())
    for (int i = 0; i < n_; ++i)
      for (int j = 0; j < n_; ++j) hv[static_cast<size_t>(i)] += xi.hess(i, j) * s.v[j];
  for (const MatrixRequest& r : m)
    for (int i = 0; i < n_; ++i)
      for (int j = 0; j < n_; ++j) {
        const double gi = xi.grad(i), gj = xi.grad(j);
        double value = 0.0;
        if (r.c.c_K != 0.0)
          value += r.c.c_K *
                   (force * xi.hess(i, j) + k_t * gi * gj + c_t * gi * hv[static_cast<size_t>(j)]);
        if (r.c.c_C != 0.0) value += r.c.c_C * c_t * gi * gj;
        r.out[i * n_ + j] = value;
      }
}

}  // namespace catena::couplings
