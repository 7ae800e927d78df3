// A spring, dashpot and actuator on a revolute or prismatic joint's coordinate
// (couplings/joint_spring.hpp), alone: the coordinate in the reference and after a known
// rotation or slide, f, K = ∂f/∂q and C = ∂f/∂v against central differences, for a joint to
// the ground and between two bodies; and the same with a moving neutral (a servo), a torque
// limit and dry friction, whose generalised force is checked against its definition.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "catena/couplings/joint_spring.hpp"
#include "catena/model/scene_reader.hpp"
#include "fd_jacobian.hpp"

namespace catena {
namespace {

using couplings::JointSpring;
using couplings::MatrixRequest;

// `extra`: more keys of the joint (", key: value, ...").
model::Model scene(const std::string& type, const std::string& b, const std::string& extra) {
  const std::string text =
      "nodes:\n"
      "  - {id: 1, position: [0.3, 0.1, 0]}\n"
      "  - {id: 2, position: [1, 0.5, -0.2]}\n"
      "supports: [{node: 2, fix: pinned}]\n"
      "analysis: {type: dynamic, duration: 1, initial: {from: reference}}\n"
      "bodies:\n"
      "  - {name: arm, node: 1, mass: 2, inertia: [0.1, 0.2, 0.25],\n"
      "     axes: [[0.8, 0.6, 0], [-0.6, 0.8, 0.1]]}\n"
      "  - {name: base, node: 2, mass: 3, inertia: [0.3, 0.2, 0.4],\n"
      "     axes: [[0, 0.6, 0.8], [1, 0, 0]]}\n"
      "joints:\n"
      "  - {type: " +
      type + ", between: [arm, " + b +
      "], point: [0.4, 0.3, 0.1], axis: [0.2, -1, 0.3],\n"
      "     stiffness: 40, damping: 1.5, neutral: 0.1, actuator: 2.5" +
      extra + "}\n";
  return model::parse_scene(text, "spring.yaml");
}

// The nodal state of the spring's DOFs: reference values, then A moved rigidly by a
// rotation about the joint's axis through its point (revolute) or a slide along it.
std::vector<double> state(const model::Model& m, const JointSpring& spring, double motion) {
  const model::Joint& joint = m.joints.front();
  const Vec3 u = joint.axis.normalized();
  std::vector<double> q;
  for (const couplings::DofKey& key : spring.dofs()) {
    const model::Node& node = m.nodes[static_cast<size_t>(key.index)];
    const Vec3* parts[4] = {&node.position, &node.tangent, &node.section_y, &node.section_z};
    Vec3 value = *parts[key.component / 3];
    if (key.index == 0) {  // body A
      if (joint.type == model::JointType::revolute) {
        const Mat3 R = Eigen::AngleAxisd(motion, u).toRotationMatrix();
        value = key.component < 3 ? Vec3(joint.point + R * (value - joint.point)) : Vec3(R * value);
      } else if (key.component < 3) {
        value += motion * u;
      }
    }
    q.push_back(value[key.component % 3]);
  }
  return q;
}

struct Case {
  std::string type, b;
  std::string extra;  // more joint keys
  std::string label;
};
// The servo, limit and friction keys of the second set of cases.
const std::string servo_keys =
    ", neutral_motion: {velocity: 0.4, amplitude: 0.2, frequency: 1.5}, limit: 6, friction: 3, "
    "stick_speed: 0.2";
constexpr double kTime = 0.37;  // s, where the cases are evaluated (the neutral moves)
class Springs : public testing::TestWithParam<Case> {};

TEST_P(Springs, CoordinateAndJacobiansMatchTheirDefinitions) {
  const Case c = GetParam();
  const model::Model m = scene(c.type, c.b, c.extra);
  const model::Joint& joint = m.joints.front();
  const JointSpring spring(m, 0);
  const auto n = static_cast<int>(spring.dofs().size());
  EXPECT_NEAR(spring.coordinate(state(m, spring, 0.0)), 0.0, 1e-14);
  EXPECT_NEAR(spring.coordinate(state(m, spring, 0.7)), 0.7, 1e-13);
  EXPECT_NEAR(spring.coordinate(state(m, spring, -0.4)), -0.4, 1e-13);
  {
    // In the reference configuration, at rest: the spring's preload only, finite.
    couplings::Scratch scratch;
    const std::vector<double> q0 = state(m, spring, 0.0);
    std::vector<double> f(static_cast<size_t>(n)), K(static_cast<size_t>(n * n));
    const MatrixRequest request[1] = {{couplings::kStaticJacobian, K.data()}};
    spring.evaluate({q0, {}, {}, kTime}, f.data(), request, scratch);
    for (double x : f) ASSERT_TRUE(std::isfinite(x));
    for (double x : K) ASSERT_TRUE(std::isfinite(x));
  }

  std::vector<double> q = state(m, spring, 0.3);
  for (int k = 0; k < n; ++k) q[static_cast<size_t>(k)] += 0.02 * std::sin(1.0 + 2.3 * k);
  std::vector<double> v(static_cast<size_t>(n));
  for (int k = 0; k < n; ++k) v[static_cast<size_t>(k)] = 0.5 * std::cos(0.7 * k);
  couplings::Scratch scratch;
  auto force_q = [&](const std::vector<double>& x, std::vector<double>& f) {
    f.assign(static_cast<size_t>(n), 0.0);
    spring.evaluate({x, v, {}, kTime}, f.data(), {}, scratch);
  };
  auto force_v = [&](const std::vector<double>& w, std::vector<double>& f) {
    f.assign(static_cast<size_t>(n), 0.0);
    spring.evaluate({q, w, {}, kTime}, f.data(), {}, scratch);
  };
  std::vector<double> K(static_cast<size_t>(n * n)), C(static_cast<size_t>(n * n));
  const MatrixRequest requests[2] = {{{1.0, 0.0, 0.0, 0.0, 0.0}, K.data()},
                                     {{0.0, 1.0, 0.0, 0.0, 0.0}, C.data()}};
  spring.evaluate({q, v, {}, kTime}, nullptr, requests, scratch);
  EXPECT_LT(test::relative_max_difference(K, test::central_difference_jacobian(force_q, q, n)),
            1e-7);
  EXPECT_LT(test::relative_max_difference(C, test::central_difference_jacobian(force_v, v, n)),
            1e-8);
  // The generalised force on the coordinate, f · ∂q/∂ξ along the joint's own motion, at the
  // rate ξ̇ = rate (v = rate ∂q/∂ξ), against its definition: the spring, dashpot and actuator
  // u = k (ξ − ξ₀(t)) + c (ξ̇ − ξ̇₀(t)) − F, capped as L tanh(u/L), plus μ ξ̇/√(ξ̇² + w²).
  const double h = 1e-6;
  const std::vector<double> q0 = state(m, spring, 0.3);
  const std::vector<double> qp = state(m, spring, 0.3 + h), qm = state(m, spring, 0.3 - h);
  std::vector<double> dq(static_cast<size_t>(n));
  for (size_t k = 0; k < dq.size(); ++k) dq[k] = (qp[k] - qm[k]) / (2 * h);
  for (const double rate : {0.0, 0.15, -2.0}) {
    std::vector<double> f(static_cast<size_t>(n)), vel(dq);
    for (double& x : vel) x *= rate;
    spring.evaluate({q0, vel, {}, kTime}, f.data(), {}, scratch);
    double generalised = 0.0;
    for (size_t k = 0; k < dq.size(); ++k) generalised += f[k] * dq[k];
    const double w = 2.0 * M_PI * joint.neutral_frequency;
    const double neutral = joint.neutral + joint.neutral_velocity * kTime +
                           joint.neutral_amplitude * std::sin(w * kTime);
    const double neutral_rate =
        joint.neutral_velocity + joint.neutral_amplitude * w * std::cos(w * kTime);
    double expected = 40.0 * (0.3 - neutral) + 1.5 * (rate - neutral_rate) - 2.5;
    if (joint.limit > 0.0) expected = joint.limit * std::tanh(expected / joint.limit);
    if (joint.friction > 0.0)
      expected += joint.friction * rate / std::hypot(rate, joint.stick_speed);
    EXPECT_NEAR(generalised, expected, 1e-7) << "rate " << rate;
  }
}

INSTANTIATE_TEST_SUITE_P(RevoluteAndPrismatic, Springs,
                         testing::Values(Case{"revolute", "ground", "", ""},
                                         Case{"revolute", "base", "", ""},
                                         Case{"prismatic", "ground", "", ""},
                                         Case{"prismatic", "base", "", ""},
                                         Case{"revolute", "ground", servo_keys, "_servo"},
                                         Case{"revolute", "base", servo_keys, "_servo"},
                                         Case{"prismatic", "ground", servo_keys, "_servo"},
                                         Case{"prismatic", "base", servo_keys, "_servo"}),
                         [](const testing::TestParamInfo<Case>& param) {
                           return param.param.type + "_" + param.param.b + param.param.label;
                         });

}  // namespace
}  // namespace catena
