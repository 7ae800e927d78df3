// Joints (couplings/joint_constraint.hpp) for every type and every kind of second side
// (a body, the ground, a node): g vanishes in the reference configuration and along rigid
// motions the joint allows, the whole matrix (Σ λ_k H_k, Gᵀ, G) matches central
// differences, and the acceleration target γ equals G a − d²g/dt² along a trajectory.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "catena/couplings/joint_constraint.hpp"
#include "catena/model/scene_reader.hpp"
#include "fd_jacobian.hpp"

namespace catena {
namespace {

using couplings::JointConstraint;
using couplings::MatrixRequest;

// Two bodies with tilted axes, a node, and one joint of `type` between `a` and `b`.
model::Model scene(const std::string& type, const std::string& b, bool driven = false) {
  const bool axis = type == "revolute" || type == "cylindrical" || type == "prismatic";
  const std::string text =
      "nodes:\n"
      "  - {id: 1, position: [0, 0, 0]}\n"
      "  - {id: 2, position: [1, 0.5, -0.2]}\n"
      "  - {id: 3, position: [0.4, 0.3, 0.1]}\n"
      "elements: []\n"
      "analysis: {type: dynamic, duration: 1, initial: {from: reference}}\n"
      "supports: [{node: 3, fix: pinned}, {node: 2, fix: pinned}]\n"
      "bodies:\n"
      "  - {name: arm, node: 1, mass: 2, inertia: [0.1, 0.2, 0.25],\n"
      "     axes: [[0.8, 0.6, 0], [-0.6, 0.8, 0.1]]}\n"
      "  - {name: base, node: 2, mass: 3, inertia: [0.3, 0.2, 0.4],\n"
      "     axes: [[0, 0.6, 0.8], [1, 0, 0]]}\n"
      "joints:\n"
      "  - {type: " +
      type + ", between: [arm, " + b + "]" + (b == "3" ? "" : ", point: [0.4, 0.3, 0.1]") +
      (axis ? ", axis: [0.2, -1, 0.3]" : "") +
      (driven ? ", motion: {velocity: 0.7, amplitude: 0.2, frequency: 1.3}" : "") + "}\n";
  return model::parse_scene(text, "joint.yaml");
}

// The joint's state: [λ, body A (12), side B]; reference values, plus a distortion.
std::vector<double> state(const model::Model& m, const JointConstraint& joint, double distortion) {
  std::vector<double> q;
  int k = 0;
  for (const couplings::DofKey& key : joint.dofs()) {
    double value = 0.3 * std::sin(1.0 + k);  // multipliers
    if (key.kind == couplings::DofKey::Kind::node) {
      const model::Node& node = m.nodes[static_cast<size_t>(key.index)];
      const Vec3* parts[4] = {&node.position, &node.tangent, &node.section_y, &node.section_z};
      value = (*parts[key.component / 3])[key.component % 3] + distortion * std::cos(2.0 + 1.7 * k);
    }
    q.push_back(value);
    ++k;
  }
  return q;
}

struct Case {
  std::string type, b;
  bool driven = false;
};
class Joints : public testing::TestWithParam<Case> {};

TEST_P(Joints, VanishInTheReferenceAndMatchFiniteDifferences) {
  const Case c = GetParam();
  const model::Model m = scene(c.type, c.b, c.driven);
  const int index = static_cast<int>(m.constraints.size()) - 1;  // the joint, last
  const JointConstraint joint(m, index);
  const auto n = static_cast<int>(joint.dofs().size());
  const int n_eq = joint.rows();
  ASSERT_EQ(n_eq, m.constraints.back().equations);
  couplings::Scratch scratch;
  std::vector<double> f(static_cast<size_t>(n));
  joint.evaluate({state(m, joint, 0.0), {}, {}, 0.0}, f.data(), {}, scratch);
  for (int k = 0; k < n_eq; ++k) EXPECT_NEAR(f[k], 0.0, 1e-14) << k;

  const std::vector<double> q = state(m, joint, 0.05);
  auto residual = [&](const std::vector<double>& x, std::vector<double>& out) {
    out.assign(static_cast<size_t>(n), 0.0);
    joint.evaluate({x, {}, {}, 0.0}, out.data(), {}, scratch);
  };
  const std::vector<double> fd = test::central_difference_jacobian(residual, q, n);
  std::vector<double> J(static_cast<size_t>(n * n));
  const MatrixRequest request[1] = {{couplings::kStaticJacobian, J.data()}};
  joint.evaluate({q, {}, {}, 0.0}, nullptr, request, scratch);
  EXPECT_LT(test::relative_max_difference(J, fd), 1e-8);

  // γ = G a − d²g/dt² along q(t).
  auto q_at = [&](double t) {
    std::vector<double> x = q;
    for (int k = n_eq; k < n; ++k)
      x[static_cast<size_t>(k)] += 0.3 * std::sin((1.0 + 0.37 * k) * t);
    return x;
  };
  const double t = 0.6, h = 1e-4;
  std::vector<double> v(static_cast<size_t>(n), 0.0), a(static_cast<size_t>(n), 0.0);
  for (int k = n_eq; k < n; ++k) {
    v[k] = (q_at(t + h)[k] - q_at(t - h)[k]) / (2 * h);
    a[k] = (q_at(t + h)[k] - 2 * q_at(t)[k] + q_at(t - h)[k]) / (h * h);
  }
  // g(q(s), s): a prescribed motion's equation depends on the time too.
  auto g = [&](double s) {
    std::vector<double> out(static_cast<size_t>(n));
    joint.evaluate({q_at(s), {}, {}, s}, out.data(), {}, scratch);
    return out;
  };
  std::vector<double> G(static_cast<size_t>(n * n));
  const MatrixRequest only_g[1] = {{{0.0, 0.0, 0.0, 0.0, 1.0}, G.data()}};
  joint.evaluate({q_at(t), {}, {}, t}, nullptr, only_g, scratch);
  std::vector<double> target(static_cast<size_t>(n_eq)), velocity(static_cast<size_t>(n_eq));
  joint.acceleration_target({q_at(t), v, {}, t}, target);
  joint.velocity_target({q_at(t), v, {}, t}, velocity);
  const std::vector<double> gp = g(t + h), g0 = g(t), gm = g(t - h);
  for (int k = 0; k < n_eq; ++k) {
    double Ga = 0.0, Gv = 0.0;
    for (int col = n_eq; col < n; ++col) {
      Ga += G[k * n + col] * a[col];
      Gv += G[k * n + col] * v[col];
    }
    EXPECT_NEAR(target[k], Ga - (gp[k] - 2 * g0[k] + gm[k]) / (h * h), 2e-5) << k;
    // β = G v − dg/dt: zero unless the joint is driven.
    EXPECT_NEAR(velocity[k], Gv - (gp[k] - gm[k]) / (2 * h), 5e-6) << k;
  }
}

INSTANTIATE_TEST_SUITE_P(
    EveryTypeAndSide, Joints,
    testing::Values(Case{"spherical", "base"}, Case{"spherical", "ground"}, Case{"spherical", "3"},
                    Case{"revolute", "base"}, Case{"revolute", "ground"},
                    Case{"cylindrical", "base"}, Case{"cylindrical", "ground"},
                    Case{"prismatic", "base"}, Case{"revolute", "ground", true},
                    Case{"revolute", "base", true}, Case{"prismatic", "ground", true},
                    Case{"prismatic", "base", true}, Case{"prismatic", "ground"},
                    Case{"fixed", "base"}, Case{"fixed", "ground"}),
    [](const testing::TestParamInfo<Case>& param) {
      return param.param.type + "_" + (param.param.b == "3" ? std::string("node") : param.param.b) +
             (param.param.driven ? "_driven" : "");
    });

// A revolute joint allows rotation about its axis and nothing else: rotate body A about the
// axis through the point (g stays 0), then about a perpendicular axis (g does not).
TEST(JointConstraint, RevoluteAllowsRotationAboutItsAxisOnly) {
  const model::Model m = scene("revolute", "ground");
  const JointConstraint joint(m, static_cast<int>(m.constraints.size()) - 1);
  const model::Joint& spec = m.joints.front();
  auto rotated = [&](const Vec3& about, double angle) {
    const Mat3 R = Eigen::AngleAxisd(angle, about.normalized()).toRotationMatrix();
    std::vector<double> q = state(m, joint, 0.0);
    const model::Node& node = m.nodes[0];
    const Vec3 r = spec.point + R * (node.position - spec.point);
    const Vec3 axes[3] = {R * node.tangent, R * node.section_y, R * node.section_z};
    for (int d = 0; d < 3; ++d) {
      q[5 + d] = r[d];
      for (int k = 0; k < 3; ++k) q[5 + 3 + 3 * k + d] = axes[k][d];
    }
    std::vector<double> f(q.size());
    couplings::Scratch scratch;
    joint.evaluate({q, {}, {}, 0.0}, f.data(), {}, scratch);
    double worst = 0.0;
    for (int k = 0; k < 5; ++k) worst = std::max(worst, std::abs(f[k]));
    return worst;
  };
  EXPECT_LT(rotated(spec.axis, 1.3), 1e-14);
  EXPECT_GT(rotated(spec.axis.cross(Vec3(1, 0, 0)), 0.3), 1e-2);
}

}  // namespace
}  // namespace catena
