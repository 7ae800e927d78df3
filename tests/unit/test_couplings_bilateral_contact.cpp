// The bilateral pantograph contact (couplings/bilateral_contact.hpp): g vanishes where the
// head sits on the wire, its matrix (Gᵀ, G) matches central differences, and the velocity
// and acceleration targets equal G v − dg/dt and G a − d²g/dt² along a trajectory while the
// contact point slides along the wire (so G turns with time).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "catena/couplings/bilateral_contact.hpp"
#include "catena/model/scene_reader.hpp"
#include "fd_jacobian.hpp"

namespace catena {
namespace {

using couplings::BilateralContact;
using couplings::MatrixRequest;

// A 30 m wire of 6 elements; the EN 50318 pantograph at 5 m running at 20 m/s, held on the
// wire by a multiplier.
model::Model scene() {
  const std::string text =
      "sections: {wire: {type: cable, EA: 1.0e7, EI: 100, mass_per_length: 1}}\n"
      "nodes:\n"
      "  - {id: 1, position: [0, 0, 5]}\n"
      "  - {id: 2, position: [30, 0, 5]}\n"
      "lines: [{name: wire, from: 1, to: 2, elements: 6, section: wire, tension: 10000}]\n"
      "supports: [{node: 1, fix: pinned}, {node: 2, fix: pinned}]\n"
      "analysis: {type: dynamic, duration: 1, initial: {from: reference}}\n"
      "pantographs:\n"
      "  - {name: p, line: wire, speed: 20, start: 5, static_force: 120, model: en50318,\n"
      "     contact: {type: bilateral}}\n";
  return model::parse_scene(text, "bilateral.yaml");
}

// Values of every DOF of the coupling at time t: reference positions and slopes, moved by
// sines of t (the multiplier made up).
std::vector<double> all_values(const model::Model& m, const BilateralContact& c, double t,
                               double amplitude) {
  std::vector<double> q;
  int k = 0;
  for (const couplings::DofKey& key : c.dofs()) {
    double value = 130.0;  // N, the multiplier
    if (key.kind == couplings::DofKey::Kind::node) {
      const model::Node& node = m.nodes[static_cast<size_t>(key.index)];
      value = (key.component < 3 ? node.position : node.tangent)[key.component % 3] +
              amplitude * std::sin((1.0 + 0.37 * k) * t + 0.3 * k);
    }
    q.push_back(value);
    ++k;
  }
  return q;
}

std::vector<double> active(const std::vector<double>& all, const std::vector<int>& positions) {
  std::vector<double> out;
  for (int p : positions) out.push_back(all[static_cast<size_t>(p)]);
  return out;
}

TEST(BilateralContact, VanishesOnTheWireAndMatchesFiniteDifferences) {
  const model::Model m = scene();
  ASSERT_EQ(m.contacts.size(), 1u);
  ASSERT_TRUE(m.contacts[0].bilateral);
  const BilateralContact c(m, m.contacts[0].constraint);
  std::vector<int> positions;
  c.active_dofs(0.0, positions);
  ASSERT_EQ(static_cast<int>(positions.size()), BilateralContact::kActive);
  const int n = BilateralContact::kActive;
  couplings::Scratch scratch;
  std::vector<double> f(static_cast<size_t>(n));
  c.evaluate({active(all_values(m, c, 0.0, 0.0), positions), {}, {}, 0.0}, f.data(), {}, scratch);
  EXPECT_NEAR(f[0], 0.0, 1e-12);  // the head starts at the wire's reference point

  for (const double t : {0.1, 0.37}) {
    c.active_dofs(t, positions);
    const std::vector<double> q = active(all_values(m, c, t, 0.05), positions);
    auto residual = [&](const std::vector<double>& x, std::vector<double>& out) {
      out.assign(static_cast<size_t>(n), 0.0);
      c.evaluate({x, {}, {}, t}, out.data(), {}, scratch);
    };
    const std::vector<double> fd = test::central_difference_jacobian(residual, q, n);
    std::vector<double> J(static_cast<size_t>(n * n));
    const MatrixRequest request[1] = {{couplings::kStaticJacobian, J.data()}};
    c.evaluate({q, {}, {}, t}, nullptr, request, scratch);
    EXPECT_LT(test::relative_max_difference(J, fd), 1e-8) << "t = " << t;
    // The head's rows carry λ·up: the wire pushes the head down by λ.
    std::vector<double> force(static_cast<size_t>(n));
    c.evaluate({q, {}, {}, t}, force.data(), {}, scratch);
    EXPECT_DOUBLE_EQ(force[3], 130.0);  // λ·up_z
  }
}

TEST(BilateralContact, TargetsMatchTheTimeDerivativesOfTheGap) {
  const model::Model m = scene();
  const BilateralContact c(m, m.contacts[0].constraint);
  const int n = BilateralContact::kActive;
  couplings::Scratch scratch;
  const double t = 0.23, h = 1e-4;  // the point at 9.6 m, inside an element for t ± h
  std::vector<int> positions;
  c.active_dofs(t, positions);
  auto q_at = [&](double s) { return active(all_values(m, c, s, 0.05), positions); };
  std::vector<double> v(static_cast<size_t>(n), 0.0), a(static_cast<size_t>(n), 0.0);
  for (int k = 1; k < n; ++k) {
    v[k] = (q_at(t + h)[k] - q_at(t - h)[k]) / (2 * h);
    a[k] = (q_at(t + h)[k] - 2 * q_at(t)[k] + q_at(t - h)[k]) / (h * h);
  }
  auto g = [&](double s) {
    std::vector<double> out(static_cast<size_t>(n));
    c.evaluate({q_at(s), {}, {}, s}, out.data(), {}, scratch);
    return out[0];
  };
  std::vector<double> G(static_cast<size_t>(n * n));
  const MatrixRequest only_g[1] = {{{0.0, 0.0, 0.0, 0.0, 1.0}, G.data()}};
  c.evaluate({q_at(t), {}, {}, t}, nullptr, only_g, scratch);
  double Gv = 0.0, Ga = 0.0;
  for (int col = 1; col < n; ++col) {
    Gv += G[static_cast<size_t>(col)] * v[static_cast<size_t>(col)];
    Ga += G[static_cast<size_t>(col)] * a[static_cast<size_t>(col)];
  }
  std::vector<double> beta(1), gamma(1);
  c.velocity_target({q_at(t), v, {}, t}, beta);
  c.acceleration_target({q_at(t), v, {}, t}, gamma);
  const double g0 = g(t), gp = g(t + h), gm = g(t - h);
  EXPECT_NEAR(beta[0], Gv - (gp - gm) / (2 * h), 1e-6);
  EXPECT_NEAR(gamma[0], Ga - (gp - 2 * g0 + gm) / (h * h), 2e-4);
  EXPECT_GT(std::abs(beta[0]), 1e-3);  // the sliding point makes them nonzero
}

}  // namespace
}  // namespace catena
