#include "catena/couplings/joint_constraint.hpp"

#include <algorithm>
#include <cmath>

#include "catena/core/error.hpp"

namespace catena::couplings {
namespace {

using Affine = JointConstraint::Affine;
using Equation = JointConstraint::Equation;

// One side of the joint: its blocks' offset in the coupling's nodal blocks and how its
// points and directions read.
struct Side {
  int first_block = 0;
  int blocks = 0;  // 4: a body, 1: a node, 0: the ground
  Vec3 r0 = Vec3::Zero();
  Mat3 R0 = Mat3::Identity();  // a body's reference axes as columns

  // The point that is at X in the reference configuration.
  Affine point(const Vec3& X, int total) const {
    Affine a{std::vector<double>(static_cast<size_t>(total), 0.0), Vec3::Zero()};
    if (blocks == 0) {
      a.constant = X;
    } else if (blocks == 1) {
      a.w[static_cast<size_t>(first_block)] = 1.0;  // the node itself (X is its position)
    } else {
      const Vec3 xi = R0.transpose() * (X - r0);  // body coordinates
      a.w[static_cast<size_t>(first_block)] = 1.0;
      for (int k = 0; k < 3; ++k) a.w[static_cast<size_t>(first_block + 1 + k)] = xi[k];
    }
    return a;
  }
  // The direction that is u in the reference configuration (a body's or the ground's).
  Affine direction(const Vec3& u, int total) const {
    Affine a{std::vector<double>(static_cast<size_t>(total), 0.0), Vec3::Zero()};
    if (blocks == 0) {
      a.constant = u;
    } else if (blocks == 4) {  // a node has no directions (its joints are spherical)
      const Vec3 c = R0.transpose() * u;
      for (int k = 0; k < 3; ++k) a.w[static_cast<size_t>(first_block + 1 + k)] = c[k];
    }
    return a;
  }
};

Affine minus(Affine a, const Affine& b) {
  for (size_t j = 0; j < a.w.size(); ++j) a.w[j] -= b.w[j];
  a.constant -= b.constant;
  return a;
}

}  // namespace

Vec3 JointConstraint::normal(const Vec3& u) {
  const Vec3 trial = std::abs(u.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  return (trial - trial.dot(u) * u).normalized();
}

JointConstraint::JointConstraint(const model::Model& model, int index) : ConstraintCoupling(index) {
  const model::Constraint& c = model.constraints[static_cast<size_t>(index)];
  CATENA_ASSERT(c.type == model::ConstraintType::joint, "JointConstraint takes a joint");
  const model::Joint& joint = model.joints[static_cast<size_t>(c.joint)];
  const int n_eq = model::joint_equations(joint);
  for (int k = 0; k < n_eq; ++k) dofs_.push_back(DofKey::multiplier(index, k));

  auto body_side = [&](int body, int first_block) {
    const model::Node& node =
        model.nodes[static_cast<size_t>(model.rigid_bodies[static_cast<size_t>(body)].node)];
    Side s{first_block, 4, node.position, Mat3::Identity()};
    s.R0.col(0) = node.tangent;
    s.R0.col(1) = node.section_y;
    s.R0.col(2) = node.section_z;
    for (int k = 0; k < 12; ++k) dofs_.push_back(DofKey::node(model.rigid_bodies[body].node, k));
    return s;
  };
  const Side a = body_side(joint.body_a, 0);
  Side b;
  if (joint.body_b >= 0) {
    b = body_side(joint.body_b, 4);
  } else if (joint.node_b >= 0) {
    b = Side{4, 1, model.nodes[static_cast<size_t>(joint.node_b)].position, Mat3::Identity()};
    for (int k = 0; k < 3; ++k) dofs_.push_back(DofKey::node(joint.node_b, k));
  }
  blocks_ = 4 + b.blocks;

  const Vec3 u = joint.axis.normalized();
  const Vec3 n1 = normal(u), n2 = u.cross(n1);
  const Affine gap = minus(a.point(joint.point, blocks_), b.point(joint.point, blocks_));
  auto component = [&](int d) { equations_.push_back({false, d, gap, {}}); };
  auto dot = [&](const Affine& x, const Affine& y) { equations_.push_back({true, 0, x, y}); };
  const Affine u_a = a.direction(u, blocks_), n1_a = a.direction(n1, blocks_);
  const Affine n1_b = b.direction(n1, blocks_), n2_b = b.direction(n2, blocks_);
  switch (joint.type) {
    case model::JointType::spherical:
      for (int d = 0; d < 3; ++d) component(d);
      break;
    case model::JointType::revolute:
      for (int d = 0; d < 3; ++d) component(d);
      dot(u_a, n1_b);
      dot(u_a, n2_b);
      break;
    case model::JointType::cylindrical:
    case model::JointType::prismatic:
      dot(u_a, n1_b);
      dot(u_a, n2_b);
      dot(gap, n1_b);
      dot(gap, n2_b);
      if (joint.type == model::JointType::prismatic) dot(n1_a, n2_b);
      break;
    case model::JointType::fixed:
      for (int d = 0; d < 3; ++d) component(d);
      dot(u_a, n1_b);
      dot(u_a, n2_b);
      dot(n1_a, n2_b);
      break;
  }
  for (size_t k = 0; k < equations_.size(); ++k) equations_[k].row = static_cast<int>(k);
  rows_ = static_cast<int>(equations_.size());
  if (joint.driven) {
    const Affine u_b = b.direction(u, blocks_);
    velocity_ = joint.motion_velocity;
    amplitude_ = joint.motion_amplitude;
    frequency_ = joint.motion_frequency;
    if (joint.type == model::JointType::revolute) {
      drive_ = Drive::angle;
      equations_.push_back({true, 0, n1_a, n2_b, rows_, 1});
      equations_.push_back({true, 0, n1_a, n1_b, rows_, 2});
    } else {
      drive_ = Drive::slide;
      equations_.push_back({true, 0, gap, u_b, rows_, 0});
    }
    ++rows_;
  }
  CATENA_ASSERT(rows_ == n_eq, "a multiplier per equation");
}

JointConstraint::Weights JointConstraint::weights(double t) const {
  Weights w;
  if (drive_ == Drive::none) return w;
  const double omega = 2.0 * M_PI * frequency_;
  const double xi = velocity_ * t + amplitude_ * std::sin(omega * t);
  const double xi_t = velocity_ + amplitude_ * omega * std::cos(omega * t);
  const double xi_tt = -amplitude_ * omega * omega * std::sin(omega * t);
  if (drive_ == Drive::slide) {
    w.offset = xi;
    w.offset_t = xi_t;
    w.offset_tt = xi_tt;
    return w;
  }
  // c₁ = cos ξ, c₂ = −sin ξ.
  const double c = std::cos(xi), s = std::sin(xi);
  w.c[1] = c;
  w.c[2] = -s;
  w.c_t[1] = -s * xi_t;
  w.c_t[2] = -c * xi_t;
  w.c_tt[1] = -c * xi_t * xi_t - s * xi_tt;
  w.c_tt[2] = s * xi_t * xi_t - c * xi_tt;
  return w;
}

bool JointConstraint::linear() const {
  // A dot of a body's direction with the ground's is linear too, but G is re-evaluated
  // only where some equation needs it: a dot with state on both sides, or a driven angle
  // (whose G turns with time).
  if (drive_ == Drive::angle) return false;
  return std::none_of(equations_.begin(), equations_.end(), [](const Equation& e) {
    if (!e.dot) return false;
    const auto moves = [](const Affine& a) {
      return std::any_of(a.w.begin(), a.w.end(), [](double w) { return w != 0.0; });
    };
    return moves(e.x) && moves(e.y);
  });
}

Vec3 JointConstraint::value(const Affine& a, std::span<const double> nodal) const {
  Vec3 x = a.constant;
  for (int j = 0; j < blocks_; ++j)
    if (const double w = a.w[static_cast<size_t>(j)]; w != 0.0)
      x += w * Vec3(nodal[3 * j], nodal[3 * j + 1], nodal[3 * j + 2]);
  return x;
}

void JointConstraint::evaluate(const CouplingState& s, double* f, std::span<const MatrixRequest> m,
                               Scratch&) const {
  const int n = rows_ + 3 * blocks_;
  const std::span<const double> nodal = s.q.subspan(static_cast<size_t>(rows_));
  const Weights w = weights(s.t);
  if (f) std::fill(f, f + n, 0.0);
  for (const MatrixRequest& r : m) std::fill(r.out, r.out + n * n, 0.0);
  for (const Equation& e : equations_) {
    const int i = e.row;
    const double c = w.c[e.weight];
    if (c == 0.0) continue;
    const double lambda = s.q[static_cast<size_t>(i)];
    const Vec3 x = value(e.x, nodal);
    const Vec3 y = e.dot ? value(e.y, nodal) : Vec3::Zero();
    // c ∂T/∂q_j: a 3-vector per block.
    auto gradient = [&](int j) -> Vec3 {
      const double wx = e.x.w[static_cast<size_t>(j)];
      if (!e.dot) return c * wx * Vec3::Unit(e.d);
      return c * (wx * y + e.y.w[static_cast<size_t>(j)] * x);
    };
    if (f) {
      f[i] += c * (e.dot ? x.dot(y) : x[e.d]);
      for (int j = 0; j < blocks_; ++j) {
        const Vec3 g = gradient(j);
        for (int d = 0; d < 3; ++d) f[rows_ + 3 * j + d] += lambda * g[d];
      }
    }
    for (const MatrixRequest& r : m) {
      for (int j = 0; j < blocks_; ++j) {
        const Vec3 g = gradient(j);
        for (int d = 0; d < 3; ++d) {
          r.out[(rows_ + 3 * j + d) * n + i] += r.c.c_lambda * g[d];
          r.out[i * n + rows_ + 3 * j + d] += r.c.c_g * g[d];
        }
      }
      if (!e.dot || r.c.c_K == 0.0) continue;
      for (int j = 0; j < blocks_; ++j)
        for (int k = 0; k < blocks_; ++k) {
          const double h = e.x.w[static_cast<size_t>(j)] * e.y.w[static_cast<size_t>(k)] +
                           e.y.w[static_cast<size_t>(j)] * e.x.w[static_cast<size_t>(k)];
          if (h == 0.0) continue;
          for (int d = 0; d < 3; ++d)
            r.out[(rows_ + 3 * j + d) * n + rows_ + 3 * k + d] += r.c.c_K * lambda * c * h;
        }
    }
  }
  if (f && drive_ == Drive::slide) f[rows_ - 1] -= w.offset;
}

void JointConstraint::acceleration_target(const CouplingState& s, std::span<double> out) const {
  // d²g/dt² = G a + Σ [c̈ T + 2 ċ Ṫ + c (T̈ − ∂T/∂q a)] − ξ̈_p, with T̈ − ∂T/∂q a = 2 ẋ·ẏ for
  // a dot and 0 for a component: γ is minus the rest.
  std::fill(out.begin(), out.end(), 0.0);
  const Weights w = weights(s.t);
  const std::span<const double> nodal = s.q.subspan(static_cast<size_t>(rows_));
  const bool moving = !s.v.empty();
  const std::span<const double> rates =
      moving ? s.v.subspan(static_cast<size_t>(rows_)) : std::span<const double>{};
  for (const Equation& e : equations_) {
    const auto i = static_cast<size_t>(e.row);
    Affine x_rate = e.x, y_rate = e.y;
    x_rate.constant = y_rate.constant = Vec3::Zero();
    const Vec3 x = value(e.x, nodal), y = e.dot ? value(e.y, nodal) : Vec3::Zero();
    const Vec3 xd = moving ? value(x_rate, rates) : Vec3::Zero();
    const Vec3 yd = moving && e.dot ? value(y_rate, rates) : Vec3::Zero();
    const double T = e.dot ? x.dot(y) : x[e.d];
    const double T_t = e.dot ? xd.dot(y) + x.dot(yd) : xd[e.d];
    const double second = e.dot ? 2.0 * xd.dot(yd) : 0.0;
    out[i] -= w.c_tt[e.weight] * T + 2.0 * w.c_t[e.weight] * T_t + w.c[e.weight] * second;
  }
  if (drive_ == Drive::slide) out[static_cast<size_t>(rows_ - 1)] += w.offset_tt;
}

void JointConstraint::velocity_target(const CouplingState& s, std::span<double> out) const {
  // dg/dt = G v + Σ ċ T − ξ̇_p = 0.
  std::fill(out.begin(), out.end(), 0.0);
  if (drive_ == Drive::none) return;
  const Weights w = weights(s.t);
  const std::span<const double> nodal = s.q.subspan(static_cast<size_t>(rows_));
  for (const Equation& e : equations_) {
    if (e.weight == 0) continue;
    const Vec3 x = value(e.x, nodal), y = value(e.y, nodal);
    out[static_cast<size_t>(e.row)] -= w.c_t[e.weight] * x.dot(y);
  }
  if (drive_ == Drive::slide) out[static_cast<size_t>(rows_ - 1)] += w.offset_t;
}

}  // namespace catena::couplings
