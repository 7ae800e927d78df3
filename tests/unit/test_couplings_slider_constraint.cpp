// The slider constraint (couplings/slider_constraint.hpp) on a path of cable elements bent
// out of its straight reference: g vanishes where the node lies on the path, the whole
// matrix (K with its s terms, C, Gᵀ, G) matches central differences wherever s lies
// (inside an element, on either side of a boundary), the acceleration target γ equals
// G a − d²g/dt² along a trajectory that crosses a boundary, and r_path and its tangent are
// continuous across the boundary.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <string>
#include <vector>

#include "catena/couplings/slider_constraint.hpp"
#include "catena/model/scene_reader.hpp"
#include "fd_jacobian.hpp"

namespace catena {
namespace {

using couplings::MatrixRequest;
using couplings::SliderConstraint;

// A 3-element cable path from (0,0,0) to (3,0,0) (nodes 1, 2 and interior 4, 5), slider
// node 3 at x = 1.3, damping 2.5; `extra` adds keys to the slider.
model::Model scene(const std::string& extra = "") {
  const std::string text =
      "sections: {wire: {type: cable, EA: 1.0e7, EI: 100, mass_per_length: 1}}\n"
      "nodes:\n"
      "  - {id: 1, position: [0, 0, 0]}\n"
      "  - {id: 2, position: [3, 0, 0]}\n"
      "  - {id: 3, position: [1.3, 0, 0]}\n"
      "lines: [{name: wire, from: 1, to: 2, elements: 3, section: wire}]\n"
      "sliders: [{name: bead, node: 3, line: wire, damping: 2.5" +
      extra +
      "}]\n"
      "masses: [{node: 3, mass: 1}]\n"
      "supports: [{node: 1, fix: pinned}, {node: 2, fix: pinned}]\n"
      "analysis: {type: dynamic, duration: 1, initial: {from: reference}}\n";
  return model::parse_scene(text, "slider.yaml");
}

// A state over all of a coupling's dofs(), read by position.
class FullValues final : public couplings::DofValues {
 public:
  explicit FullValues(std::span<const double> q) : q_(q) {}
  double at(int position) const override { return q_[static_cast<size_t>(position)]; }

 private:
  std::span<const double> q_;
};

// The part of a state over dofs() that the slider acts on, as the system gathers it.
struct ActivePart {
  std::vector<int> positions;
  std::vector<double> q, v;
};
ActivePart active_part(const SliderConstraint& slider, const couplings::CouplingState& full) {
  ActivePart a;
  slider.active_dofs_at(full.t, FullValues(full.q), a.positions);
  for (const int p : a.positions) {
    a.q.push_back(full.q[static_cast<size_t>(p)]);
    if (!full.v.empty()) a.v.push_back(full.v[static_cast<size_t>(p)]);
  }
  return a;
}

// The slider evaluated as the system evaluates it (on the DOFs it picks from the state), its
// force and matrices scattered back to the positions of dofs(), zero elsewhere: so that
// central differences over all of dofs() check the choice too.
void evaluate_full(const SliderConstraint& slider, const couplings::CouplingState& full, double* f,
                   std::span<const MatrixRequest> m, couplings::Scratch& scratch) {
  const size_t n = slider.dofs().size();
  const ActivePart a = active_part(slider, full);
  const size_t na = a.positions.size();
  EXPECT_EQ(na, static_cast<size_t>(SliderConstraint::kPath + 12));
  std::vector<double> fa(na);
  std::vector<std::vector<double>> blocks(m.size(), std::vector<double>(na * na));
  std::vector<MatrixRequest> requests;
  for (size_t k = 0; k < m.size(); ++k) requests.push_back({m[k].c, blocks[k].data()});
  slider.evaluate({a.q, a.v, full.path, full.t}, f ? fa.data() : nullptr, requests, scratch);
  if (f) {
    std::fill(f, f + n, 0.0);
    for (size_t i = 0; i < na; ++i) f[a.positions[i]] = fa[i];
  }
  for (size_t k = 0; k < m.size(); ++k) {
    std::fill(m[k].out, m[k].out + n * n, 0.0);
    for (size_t i = 0; i < na; ++i)
      for (size_t j = 0; j < na; ++j)
        m[k].out[static_cast<size_t>(a.positions[i]) * n + static_cast<size_t>(a.positions[j])] =
            blocks[k][i * na + j];
  }
}

void acceleration_target_full(const SliderConstraint& slider, const couplings::CouplingState& full,
                              std::span<double> out) {
  const ActivePart a = active_part(slider, full);
  slider.acceleration_target({a.q, a.v, full.path, full.t}, out);
}

// The static Jacobian (∂f/∂q with Gᵀ and G, within 1e-7) and ∂f/∂v (within c_tolerance)
// at (q, v) over all of dofs() against central differences; returns ∂f/∂v.
std::vector<double> check_matrices(const SliderConstraint& slider, const std::vector<double>& q,
                                   const std::vector<double>& v, double c_tolerance,
                                   couplings::Scratch& scratch) {
  const auto n = static_cast<int>(slider.dofs().size());
  auto residual = [&](const std::vector<double>& x, std::vector<double>& out) {
    out.assign(static_cast<size_t>(n), 0.0);
    evaluate_full(slider, {x, v, {}, 0.0}, out.data(), {}, scratch);
  };
  const std::vector<double> fd = test::central_difference_jacobian(residual, q, n, 1e-7);
  std::vector<double> J(static_cast<size_t>(n * n));
  const MatrixRequest request[1] = {{couplings::kStaticJacobian, J.data()}};
  evaluate_full(slider, {q, v, {}, 0.0}, nullptr, request, scratch);
  EXPECT_LT(test::relative_max_difference(J, fd), 1e-7);
  auto in_rates = [&](const std::vector<double>& u, std::vector<double>& out) {
    out.assign(static_cast<size_t>(n), 0.0);
    evaluate_full(slider, {q, u, {}, 0.0}, out.data(), {}, scratch);
  };
  const std::vector<double> fd_c = test::central_difference_jacobian(in_rates, v, n, 1e-7);
  std::vector<double> C(static_cast<size_t>(n * n));
  const MatrixRequest only_c[1] = {{{0.0, 1.0, 0.0, 0.0, 0.0}, C.data()}};
  evaluate_full(slider, {q, v, {}, 0.0}, nullptr, only_c, scratch);
  EXPECT_LT(test::relative_max_difference(C, fd_c), c_tolerance);
  return C;
}

// [λ, r, s, path nodes' r and r_x]: reference values (s = `slide`), the path and the node
// distorted, multipliers and rates made up.
std::vector<double> state(const model::Model& m, const SliderConstraint& slider, double slide,
                          double distortion) {
  std::vector<double> q;
  int k = 0;
  for (const couplings::DofKey& key : slider.dofs()) {
    double value = 0.3 * std::sin(1.0 + k);  // multipliers
    if (key.kind == couplings::DofKey::Kind::node) {
      const model::Node& node = m.nodes[static_cast<size_t>(key.index)];
      if (key.component == 3 && key.index == m.sliders[0].node)
        value = slide;
      else
        value = (key.component < 3 ? node.position : node.tangent)[key.component % 3] +
                distortion * std::cos(2.0 + 1.7 * k);
    }
    q.push_back(value);
    ++k;
  }
  return q;
}

TEST(SliderConstraint, VanishesOnThePathAndMatchesFiniteDifferences) {
  const model::Model m = scene();
  ASSERT_EQ(m.sliders.size(), 1u);
  EXPECT_NEAR(m.sliders[0].start, 1.3, 1e-12);
  const SliderConstraint slider(m, m.sliders[0].constraint);
  const auto n = static_cast<int>(slider.dofs().size());
  EXPECT_EQ(n, 7 + 4 * 6);
  couplings::Scratch scratch;
  std::vector<double> f(static_cast<size_t>(n));
  evaluate_full(slider, {state(m, slider, 1.3, 0.0), {}, {}, 0.0}, f.data(), {}, scratch);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(f[k], 0.0, 1e-14) << k;

  // Inside the first element, inside the second, and just either side of their boundary.
  for (const double slide : {0.4, 1.3, 1.0 - 1e-3, 1.0 + 1e-3}) {
    SCOPED_TRACE("s = " + std::to_string(slide));
    const std::vector<double> q = state(m, slider, slide, 0.05);
    std::vector<double> v(static_cast<size_t>(n));
    for (int k = 0; k < n; ++k) v[static_cast<size_t>(k)] = 0.2 * std::cos(0.3 + k);
    // ∂f/∂v: the damping on s alone.
    const std::vector<double> C = check_matrices(slider, q, v, 1e-8, scratch);
    EXPECT_DOUBLE_EQ(C[static_cast<size_t>(SliderConstraint::kSlide * (n + 1))], 2.5);
  }
}

// Coulomb friction μ |t × λ| φ(ṡ) on the s row: the matrix (its λ columns, its K terms
// through the tangent, its C term through φ') against central differences, on both sides
// of an element boundary, sliding each way, and a speed below the stick speed.
TEST(SliderConstraint, CoulombFrictionMatchesFiniteDifferences) {
  const model::Model m = scene(", friction: 0.4, stick_speed: 0.05");
  ASSERT_EQ(m.sliders.size(), 1u);
  EXPECT_DOUBLE_EQ(m.sliders[0].friction, 0.4);
  const SliderConstraint slider(m, m.sliders[0].constraint);
  EXPECT_TRUE(slider.has_damping());
  const auto n = static_cast<int>(slider.dofs().size());
  couplings::Scratch scratch;
  for (const double slide : {0.4, 1.0 - 1e-3, 1.0 + 1e-3})
    for (const double rate : {0.3, -0.2, 0.02}) {
      SCOPED_TRACE("s = " + std::to_string(slide) + ", ds/dt = " + std::to_string(rate));
      const std::vector<double> q = state(m, slider, slide, 0.05);
      std::vector<double> v(static_cast<size_t>(n));
      for (int k = 0; k < n; ++k) v[static_cast<size_t>(k)] = 0.2 * std::cos(0.3 + k);
      v[SliderConstraint::kSlide] = rate;
      check_matrices(slider, q, v, 1e-7, scratch);
      // The force itself: μ |t × λ| φ(ṡ) beyond the viscous part.
      std::vector<double> f(static_cast<size_t>(n));
      evaluate_full(slider, {q, v, {}, 0.0}, f.data(), {}, scratch);
      std::vector<double> f_static(static_cast<size_t>(n));
      evaluate_full(slider, {q, {}, {}, 0.0}, f_static.data(), {}, scratch);
      const double coulomb =
          f[SliderConstraint::kSlide] - f_static[SliderConstraint::kSlide] - 2.5 * rate;
      EXPECT_GT(coulomb * rate, 0.0);  // opposes the motion (the s row is t·λ's balance)
      for (int k = 0; k < n; ++k) {
        if (k == SliderConstraint::kSlide) continue;
        EXPECT_EQ(f[static_cast<size_t>(k)], f_static[static_cast<size_t>(k)]) << k;
      }
    }
}

TEST(SliderConstraint, AccelerationTargetAlongATrajectoryAcrossABoundary) {
  const model::Model m = scene();
  const SliderConstraint slider(m, m.sliders[0].constraint);
  const auto n = static_cast<int>(slider.dofs().size());
  couplings::Scratch scratch;
  const std::vector<double> q0 = state(m, slider, 0.0, 0.05);
  // s(t) = 0.97 + 0.2 t crosses the boundary at 1 m at t = 0.15; the rest moves as sines.
  auto q_at = [&](double t) {
    std::vector<double> x = q0;
    for (int k = 3; k < n; ++k) x[static_cast<size_t>(k)] += 0.03 * std::sin((1.0 + 0.37 * k) * t);
    x[SliderConstraint::kSlide] = 0.97 + 0.2 * t + 0.05 * t * t;
    return x;
  };
  const double h = 1e-4;
  for (const double t : {0.05, 0.3}) {  // before and after the crossing
    std::vector<double> v(static_cast<size_t>(n), 0.0), a(static_cast<size_t>(n), 0.0);
    for (int k = 3; k < n; ++k) {
      v[k] = (q_at(t + h)[k] - q_at(t - h)[k]) / (2 * h);
      a[k] = (q_at(t + h)[k] - 2 * q_at(t)[k] + q_at(t - h)[k]) / (h * h);
    }
    auto g = [&](double s) {
      std::vector<double> out(static_cast<size_t>(n));
      evaluate_full(slider, {q_at(s), {}, {}, s}, out.data(), {}, scratch);
      return out;
    };
    std::vector<double> G(static_cast<size_t>(n * n));
    const MatrixRequest only_g[1] = {{{0.0, 0.0, 0.0, 0.0, 1.0}, G.data()}};
    evaluate_full(slider, {q_at(t), {}, {}, t}, nullptr, only_g, scratch);
    std::vector<double> target(3), velocity(3);
    acceleration_target_full(slider, {q_at(t), v, {}, t}, target);
    slider.velocity_target({q_at(t), v, {}, t}, velocity);
    const std::vector<double> gp = g(t + h), g0 = g(t), gm = g(t - h);
    for (int k = 0; k < 3; ++k) {
      double Ga = 0.0;
      for (int col = 3; col < n; ++col) Ga += G[k * n + col] * a[col];
      EXPECT_NEAR(target[k], Ga - (gp[k] - 2 * g0[k] + gm[k]) / (h * h), 2e-5) << k;
      EXPECT_EQ(velocity[k], 0.0);
    }
  }
}

TEST(SliderConstraint, PathPointAndTangentAreContinuousAcrossAnElementBoundary) {
  const model::Model m = scene();
  const SliderConstraint slider(m, m.sliders[0].constraint);
  const auto n = static_cast<int>(slider.dofs().size());
  couplings::Scratch scratch;
  // g = r − r_path(s) with r fixed: its jump across s = 1 is r_path's, its s-derivative
  // (the G column of s) is −t.
  auto at = [&](double slide, std::vector<double>& g, std::vector<double>& G) {
    const std::vector<double> q = state(m, slider, slide, 0.05);
    g.assign(static_cast<size_t>(n), 0.0);
    G.assign(static_cast<size_t>(n * n), 0.0);
    const MatrixRequest only_g[1] = {{{0.0, 0.0, 0.0, 0.0, 1.0}, G.data()}};
    evaluate_full(slider, {q, {}, {}, 0.0}, g.data(), only_g, scratch);
  };
  std::vector<double> g_below, G_below, g_above, G_above;
  const double e = 1e-9;
  at(1.0 - e, g_below, G_below);
  at(1.0 + e, g_above, G_above);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(g_below[k], g_above[k], 1e-8) << k;
    const size_t column = static_cast<size_t>(k * n + SliderConstraint::kSlide);
    EXPECT_NEAR(G_below[column], G_above[column], 1e-7) << k;
  }
}

}  // namespace
}  // namespace catena
