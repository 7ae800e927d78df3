// The pantograph contact law alone: its force against the closed form, its Jacobians
// against finite differences, and which DOFs it acts on as it travels.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/couplings/pantograph_contact.hpp"
#include "fd_jacobian.hpp"
#include "model_builders.hpp"

namespace catena {
namespace {

using couplings::CouplingState;
using couplings::JacobianCoefficients;
using couplings::MatrixRequest;
using couplings::PantographContact;

// A 10 m wire of 5 cables along x and a head node below it, the head travelling at 20 m/s
// from 3.1 m (inside element 1, [2, 4] m) for `duration` s: by 0.5 s it has left the path.
struct ContactModel {
  model::Model m;
  ContactModel(double stiffness = 5e4, double damping = 80.0, double duration = 0.5) {
    m.analysis = model::AnalysisType::dynamic;
    m.dynamic_options.duration = duration;
    model::CableProps cable;
    cable.EA = 1e7;
    cable.EI = 100.0;
    cable.mass_per_length = 1.0;
    const std::vector<int> wire = test::add_line(m, {0, 0, 0}, {10, 0, 0}, 5, cable);
    test::set_reference_frames(m);
    model::Node head;
    head.id = 100;
    head.position = Vec3(3.1, 0, -0.01);
    m.nodes.push_back(head);
    m.paths.push_back({"cw", {0, 1, 2, 3, 4}});
    model::MovingContact c;
    c.head_node = static_cast<int>(m.nodes.size()) - 1;
    c.path = 0;
    c.speed = 20.0;
    c.start = 3.1;
    c.stiffness = stiffness;
    c.damping = damping;
    m.contacts.push_back(c);
  }
};

// The reference values of the active DOFs, the head raised by `lift`.
std::vector<double> reference_active(const model::Model& m, const PantographContact& c, double t,
                                     double lift) {
  std::vector<int> active;
  c.active_dofs(t, active);
  std::vector<double> q;
  for (int pos : active) {
    const couplings::DofKey key = c.dofs()[static_cast<size_t>(pos)];
    const model::Node& n = m.nodes[static_cast<size_t>(key.index)];
    q.push_back(key.component < 3 ? n.position[key.component] : n.tangent[key.component - 3]);
  }
  q[2] += lift;
  return q;
}

TEST(PantographContact, ActsOnTheHeadAndTheWireElementUnderIt) {
  ContactModel cm;
  const PantographContact c(cm.m, 0);
  // The head and the wire nodes it reaches with their slopes: from 3.1 − 1 m on, element 1
  // to the end, nodes 1 to 5 (node 0 is never under it).
  EXPECT_EQ(c.dofs().size(), 3u + 5u * 6u);
  std::vector<int> active;
  c.active_dofs(0.0, active);  // s = 3.1 m: element 1, nodes 1 and 2
  ASSERT_EQ(active.size(), 15u);
  EXPECT_EQ(c.dofs()[static_cast<size_t>(active[3])].index, 1);
  EXPECT_EQ(c.dofs()[static_cast<size_t>(active[9])].index, 2);
  c.active_dofs(0.1, active);  // s = 5.1 m: element 2, nodes 2 and 3
  EXPECT_EQ(c.dofs()[static_cast<size_t>(active[3])].index, 2);
  c.active_dofs(0.4, active);  // s = 11.1 m: beyond the path
  EXPECT_TRUE(active.empty());
  EXPECT_FALSE(c.on_path(0.4));
}

TEST(PantographContact, ForceIsThePenaltyOfThePenetration) {
  ContactModel cm(5e4, 0.0);
  const PantographContact c(cm.m, 0);
  // The head 0.01 m below the straight wire: separated; lifted by 0.013 m: 3 mm into it.
  std::vector<double> q = reference_active(cm.m, c, 0.0, 0.0);
  double delta = 0.0;
  EXPECT_EQ(c.force({q, {}, {}, 0.0}, &delta), 0.0);
  EXPECT_NEAR(delta, -0.01, 1e-14);
  q = reference_active(cm.m, c, 0.0, 0.013);
  EXPECT_NEAR(c.force({q, {}, {}, 0.0}, &delta), 5e4 * 0.003, 1e-9);
  EXPECT_NEAR(delta, 0.003, 1e-14);
  std::vector<double> f(15);
  couplings::Scratch scratch;
  c.evaluate({q, {}, {}, 0.0}, f.data(), {}, scratch);
  // The head is pushed down and the wire up by the same force (S1 + S3 = 1 at any point).
  EXPECT_NEAR(f[2], 150.0, 1e-9);
  EXPECT_NEAR(f[5] + f[11], -150.0, 1e-9);
}

TEST(PantographContact, JacobiansMatchFiniteDifferences) {
  ContactModel cm;
  const PantographContact c(cm.m, 0);
  const double t = 0.013;  // s = 3.36 m, inside element 1
  std::vector<double> q = reference_active(cm.m, c, t, 0.012);
  q[4] += 0.002;  // wire node 1 moved up a little, its slope tilted
  q[8] += 0.001;
  std::vector<double> v(15, 0.0);
  v[2] = 0.3;
  v[11] = -0.1;
  couplings::Scratch scratch;
  auto f_of_q = [&](const std::vector<double>& x, std::vector<double>& f) {
    f.assign(15, 0.0);
    c.evaluate({x, v, {}, t}, f.data(), {}, scratch);
  };
  auto f_of_v = [&](const std::vector<double>& x, std::vector<double>& f) {
    f.assign(15, 0.0);
    c.evaluate({q, x, {}, t}, f.data(), {}, scratch);
  };
  const std::vector<double> K_fd = test::central_difference_jacobian(f_of_q, q, 15, 1e-7);
  const std::vector<double> C_fd = test::central_difference_jacobian(f_of_v, v, 15, 1e-7);
  std::vector<double> K(225), C(225), J(225);
  const MatrixRequest requests[3] = {{JacobianCoefficients{1.0, 0.0, 0.0}, K.data()},
                                     {JacobianCoefficients{0.0, 1.0, 0.0}, C.data()},
                                     {JacobianCoefficients{2.0, 0.5, 7.0}, J.data()}};
  c.evaluate({q, v, {}, t}, nullptr, requests, scratch);
  EXPECT_LT(test::relative_max_difference(K, K_fd), 1e-6);
  EXPECT_LT(test::relative_max_difference(C, C_fd), 1e-6);
  // A combination is the combination of the parts (the contact has no mass).
  for (size_t i = 0; i < J.size(); ++i) EXPECT_NEAR(J[i], 2.0 * K[i] + 0.5 * C[i], 1e-9);
  // Out of contact everything vanishes.
  const std::vector<double> apart = reference_active(cm.m, c, t, 0.0);
  c.evaluate({apart, v, {}, t}, nullptr, requests, scratch);
  for (double x : K) EXPECT_EQ(x, 0.0);
}

TEST(PantographContact, PatternCouplesTheHeadWithThePathItReaches) {
  ContactModel cm;
  const PantographContact c(cm.m, 0);
  std::vector<std::pair<int, int>> entries;
  c.pattern(entries);
  const int n = static_cast<int>(c.dofs().size());
  EXPECT_EQ(entries.size(), static_cast<size_t>(3 * n + 3 * (n - 3)));
  for (auto [r, col] : entries) EXPECT_TRUE(r < 3 || col < 3);
}

// A short run reaches part of the path only: the pattern holds those nodes, and a contact
// point beyond them (a time past the analysis) is an error that names the pantograph, not
// entries outside the pattern.
TEST(PantographContact, AShortRunCouplesTheHeadToThePartOfThePathItCrosses) {
  ContactModel cm(5e4, 80.0, 0.05);  // s from 3.1 to 4.1 m: with the 1 m margin, [2.1, 5.1]
  cm.m.contacts[0].name = "leading";
  const PantographContact c(cm.m, 0);
  EXPECT_EQ(c.dofs().size(), 3u + 3u * 6u);  // elements 1 and 2: nodes 1, 2, 3
  std::vector<int> active;
  c.active_dofs(0.05, active);
  EXPECT_EQ(active.size(), 15u);
  try {
    c.active_dofs(0.3, active);  // s = 9.1 m, on the path but never reached in the run
    ADD_FAILURE() << "no error beyond the reach";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("pantograph 'leading'"), std::string::npos) << e.what();
  }
  // A static analysis: the pantograph standing at its start.
  cm.m.analysis = model::AnalysisType::static_equilibrium;
  const PantographContact standing(cm.m, 0);
  EXPECT_EQ(standing.dofs().size(), 3u + 3u * 6u);  // [2.1, 4.1]: elements 1 and 2
}

}  // namespace
}  // namespace catena
