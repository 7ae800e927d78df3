#include "catena/couplings/joint_constraint.hpp"

#include <algorithm>

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

// A unit vector perpendicular to u.
Vec3 perpendicular(const Vec3& u) {
  const Vec3 trial = std::abs(u.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  return (trial - trial.dot(u) * u).normalized();
}

}  // namespace

JointConstraint::JointConstraint(const model::Model& model, int index) : ConstraintCoupling(index) {
  const model::Constraint& c = model.constraints[static_cast<size_t>(index)];
  CATENA_ASSERT(c.type == model::ConstraintType::joint, "JointConstraint takes a joint");
  const model::Joint& joint = model.joints[static_cast<size_t>(c.joint)];
  const int n_eq = model::joint_equations(joint.type);
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
  const Vec3 n1 = perpendicular(u), n2 = u.cross(n1);
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
  CATENA_ASSERT(static_cast<int>(equations_.size()) == n_eq, "a multiplier per equation");
}

bool JointConstraint::linear() const {
  // A dot of a body's direction with the ground's is linear too, but G is re-evaluated
  // only where some equation needs it: a dot with state on both sides.
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
  const auto n_eq = static_cast<int>(equations_.size());
  const int n = n_eq + 3 * blocks_;
  const std::span<const double> nodal = s.q.subspan(static_cast<size_t>(n_eq));
  if (f) std::fill(f, f + n, 0.0);
  for (const MatrixRequest& r : m) std::fill(r.out, r.out + n * n, 0.0);
  for (int i = 0; i < n_eq; ++i) {
    const Equation& e = equations_[static_cast<size_t>(i)];
    const double lambda = s.q[static_cast<size_t>(i)];
    const Vec3 x = value(e.x, nodal);
    const Vec3 y = e.dot ? value(e.y, nodal) : Vec3::Zero();
    // ∂g/∂q_j: a 3-vector per block.
    auto gradient = [&](int j) -> Vec3 {
      const double w = e.x.w[static_cast<size_t>(j)];
      if (!e.dot) return w * Vec3::Unit(e.d);
      return w * y + e.y.w[static_cast<size_t>(j)] * x;
    };
    if (f) {
      f[i] = e.dot ? x.dot(y) : x[e.d];
      for (int j = 0; j < blocks_; ++j) {
        const Vec3 g = gradient(j);
        for (int d = 0; d < 3; ++d) f[n_eq + 3 * j + d] += lambda * g[d];
      }
    }
    for (const MatrixRequest& r : m) {
      for (int j = 0; j < blocks_; ++j) {
        const Vec3 g = gradient(j);
        for (int d = 0; d < 3; ++d) {
          r.out[(n_eq + 3 * j + d) * n + i] += r.c.c_lambda * g[d];
          r.out[i * n + n_eq + 3 * j + d] += r.c.c_g * g[d];
        }
      }
      if (!e.dot || r.c.c_K == 0.0) continue;
      for (int j = 0; j < blocks_; ++j)
        for (int k = 0; k < blocks_; ++k) {
          const double h = e.x.w[static_cast<size_t>(j)] * e.y.w[static_cast<size_t>(k)] +
                           e.y.w[static_cast<size_t>(j)] * e.x.w[static_cast<size_t>(k)];
          if (h == 0.0) continue;
          for (int d = 0; d < 3; ++d)
            r.out[(n_eq + 3 * j + d) * n + n_eq + 3 * k + d] += r.c.c_K * lambda * h;
        }
    }
  }
}

void JointConstraint::acceleration_target(const CouplingState& s, std::span<double> out) const {
  const auto n_eq = static_cast<int>(equations_.size());
  std::fill(out.begin(), out.end(), 0.0);
  if (s.v.empty()) return;  // at rest: vᵀ H v = 0
  const std::span<const double> rates = s.v.subspan(static_cast<size_t>(n_eq));
  for (int i = 0; i < n_eq; ++i) {
    const Equation& e = equations_[static_cast<size_t>(i)];
    if (!e.dot) continue;  // linear: G a = 0 (no prescribed motion)
    // ẋ, ẏ: the affine maps' linear parts applied to v.
    Affine x_rate = e.x, y_rate = e.y;
    x_rate.constant = y_rate.constant = Vec3::Zero();
    out[static_cast<size_t>(i)] = -2.0 * value(x_rate, rates).dot(value(y_rate, rates));
  }
}

}  // namespace catena::couplings
