#include "catena/solvers/statics/hanging_cable_guess.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <variant>

#include "catena/assembly/petsc_call.hpp"
#include "catena/model/unknown_kinds.hpp"

namespace catena::solvers {
namespace {

constexpr unsigned kPosition = 0b111u;         // fixed-mask bits of x, y, z
constexpr unsigned kSlope = 0b111u << 3;       // of r_x
constexpr double kFixedValueTolerance = 1e-9;  // relative: a held component the guess keeps

// Irvine's elastic catenary in the plane of the chord and the load, with H the tension's
// horizontal component and V0 its vertical one (up) at the start, s the unstretched arc
// length, q the weight per unstretched length:
//   x(s) = H s/EA + (H/q) [asinh((V0 + q s)/H) − asinh(V0/H)]
//   z(s) = (V0 s + q s²/2)/EA + (H/q) [√(1 + ((V0 + q s)/H)²) − √(1 + (V0/H)²)].
struct PlaneCatenary {
  double L0, EA, q;

  Eigen::Vector2d end(double H, double V0) const {
    const double a = V0 / H, b = (V0 + q * L0) / H;
    return {
        H * L0 / EA + H / q * (std::asinh(b) - std::asinh(a)),
        (V0 * L0 + 0.5 * q * L0 * L0) / EA + H / q * (std::sqrt(1 + b * b) - std::sqrt(1 + a * a))};
  }
  // ∂(x, z)(L0)/∂(H, V0), differentiated by hand.
  Eigen::Matrix2d end_jacobian(double H, double V0) const {
    const double a = V0 / H, b = (V0 + q * L0) / H;
    const double ra = 1 / std::sqrt(1 + a * a), rb = 1 / std::sqrt(1 + b * b);
    Eigen::Matrix2d J;
    J << L0 / EA + (std::asinh(b) - std::asinh(a) - (b * rb - a * ra)) / q, (rb - ra) / q,
        (rb - ra) / q, L0 / EA + (b * rb - a * ra) / q;
    return J;
  }
  Eigen::Vector2d at(double H, double V0, double s) const {
    return PlaneCatenary{s, EA, q}.end(H, V0);
  }
};

// The tension components (H, V0) that put the end of `c` at (h, v); none if Newton, halving
// its steps to keep H > 0 and the miss decreasing, does not get there.
std::optional<Eigen::Vector2d> solve_end_tensions(const PlaneCatenary& c, double h, double v,
                                                  double chord) {
  // A taut cable's tension is about EA times its strain, a slack one's about its weight.
  const double H0 = std::max(c.q * c.L0, c.EA * std::max(0.0, chord / c.L0 - 1.0));
  Eigen::Vector2d x(H0, H0 * v / h - 0.5 * c.q * c.L0);
  const Eigen::Vector2d target(h, v);
  Eigen::Vector2d miss = c.end(x[0], x[1]) - target;
  for (int it = 0; it < 200; ++it) {
    if (miss.norm() <= 1e-12 * (c.L0 + chord)) return x;
    const Eigen::Vector2d step = c.end_jacobian(x[0], x[1]).fullPivLu().solve(miss);
    double alpha = 1.0;
    for (; alpha > 1e-10; alpha *= 0.5) {
      const Eigen::Vector2d trial = x - alpha * step;
      if (!(trial[0] > 0.0)) continue;
      const Eigen::Vector2d trial_miss = c.end(trial[0], trial[1]) - target;
      if (trial_miss.norm() < miss.norm()) {
        x = trial;
        miss = trial_miss;
        break;
      }
    }
    if (alpha <= 1e-10) return std::nullopt;
  }
  return std::nullopt;
}

// One line: its nodes from one pinned end to the other and its elements between them.
struct Chain {
  std::vector<int> nodes, elements;
};

bool same_section(const model::CableProps& a, const model::CableProps& b) {
  return a.EA == b.EA && a.mass_per_length == b.mass_per_length && a.prestrain == b.prestrain;
}

}  // namespace

std::optional<std::vector<CatenaryPoint>> elastic_catenary_points(const Vec3& a, const Vec3& b,
                                                                  double L0, double EA, double q,
                                                                  const Vec3& down,
                                                                  const std::vector<double>& s) {
  const Vec3 up = -down.normalized();
  const Vec3 chord = b - a;
  const double v = chord.dot(up);
  const Vec3 across = chord - v * up;
  const double h = across.norm();
  if (!(h > 1e-9 * chord.norm()) || !(q > 0.0)) return std::nullopt;
  const Vec3 e_h = across / h;
  const PlaneCatenary c{L0, EA, q};
  const std::optional<Eigen::Vector2d> tensions = solve_end_tensions(c, h, v, chord.norm());
  if (!tensions) return std::nullopt;
  const double H = (*tensions)[0], V0 = (*tensions)[1];
  std::vector<CatenaryPoint> points;
  for (const double si : s) {
    const Eigen::Vector2d p = c.at(H, V0, si);
    const Vec3 t = H * e_h + (V0 + q * si) * up;
    points.push_back({a + p[0] * e_h + p[1] * up, t / t.norm() + t / EA});
  }
  return points;
}

std::optional<std::vector<NodeGuess>> hanging_cable_guess(const model::Model& m) {
  const auto none = std::nullopt;
  const std::size_t n_nodes = m.nodes.size();
  if (m.elements.empty() || !(m.gravity.norm() > 0.0) || !m.point_masses.empty() ||
      !m.elastic_supports.empty() || !m.constraints.empty() || !m.moving_loads.empty() ||
      !m.contacts.empty() || !m.surfaces.empty())
    return none;
  for (const model::NodalLoad& load : m.nodal_loads)
    if (load.force != Vec3::Zero()) return none;
  std::vector<unsigned> mask(n_nodes, 0u);
  std::vector<bool> clamped(n_nodes, false);
  for (const model::Support& support : m.supports) {
    mask[static_cast<std::size_t>(support.node)] |= support.fixed_mask;
    if (support.slope_direction) clamped[static_cast<std::size_t>(support.node)] = true;
  }
  const auto pinned = [&](int node) {
    const auto k = static_cast<std::size_t>(node);
    return (mask[k] & kPosition) == kPosition && (mask[k] & kSlope) == 0u && !clamped[k];
  };
  // Each node starts at most one element and ends at most one: no branches.
  std::vector<int> starting(n_nodes, -1), ending(n_nodes, -1);
  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    const model::ElementDesc& element = m.elements[e];
    const auto* cable = std::get_if<model::CableProps>(&*element.props);
    if (cable == nullptr || element.nodes.size() != 2 || cable->prestrain_with_loads ||
        element.distributed_load != Vec3::Zero())
      return none;
    int& out = starting[static_cast<std::size_t>(element.nodes[0])];
    int& in = ending[static_cast<std::size_t>(element.nodes[1])];
    if (out >= 0 || in >= 0) return none;
    out = in = static_cast<int>(e);
  }
  // Lines from a pinned node to the next pinned node along the elements' direction.
  std::vector<Chain> chains;
  std::size_t covered = 0;
  for (std::size_t n = 0; n < n_nodes; ++n) {
    const int first = static_cast<int>(n);
    if (starting[n] < 0 || (ending[n] >= 0 && !pinned(first))) continue;
    if (!pinned(first)) return none;
    Chain chain{{first}, {}};
    int node = first;
    do {
      const int e = starting[static_cast<std::size_t>(node)];
      if (e < 0) return none;  // a free end
      chain.elements.push_back(e);
      node = m.elements[static_cast<std::size_t>(e)].nodes[1];
      chain.nodes.push_back(node);
    } while (!pinned(node));
    covered += chain.elements.size();
    chains.push_back(std::move(chain));
  }
  if (covered != m.elements.size()) return none;  // a closed loop, or a line not pinned

  std::vector<NodeGuess> guess;
  const Vec3 down = m.gravity.normalized();
  for (const Chain& chain : chains) {
    const auto& section =
        std::get<model::CableProps>(*m.elements[static_cast<std::size_t>(chain.elements[0])].props);
    std::vector<double> s{0.0};
    for (const int e : chain.elements) {
      const auto& element = m.elements[static_cast<std::size_t>(e)];
      if (!same_section(section, std::get<model::CableProps>(*element.props))) return none;
      const double mesh_length = (m.nodes[static_cast<std::size_t>(element.nodes[1])].position -
                                  m.nodes[static_cast<std::size_t>(element.nodes[0])].position)
                                     .norm();
      s.push_back(s.back() + mesh_length / (1.0 + section.prestrain));
    }
    const Vec3& a = m.nodes[static_cast<std::size_t>(chain.nodes.front())].position;
    const Vec3& b = m.nodes[static_cast<std::size_t>(chain.nodes.back())].position;
    const auto points = elastic_catenary_points(
        a, b, s.back(), section.EA, section.mass_per_length * m.gravity.norm(), down, s);
    if (!points) return none;
    for (std::size_t i = 0; i < chain.nodes.size(); ++i) {
      const int node = chain.nodes[i];
      // r_x is the derivative along the mesh coordinate: ds0/dX = 1/(1 + prestrain).
      NodeGuess g{node, (*points)[i].position, (*points)[i].tangent / (1.0 + section.prestrain)};
      // A component the node holds must keep its reference value (a planar line's y).
      const auto& element = m.elements[static_cast<std::size_t>(
          chain.elements[std::min(i, chain.elements.size() - 1)])];
      const Vec3 reference_slope = (m.nodes[static_cast<std::size_t>(element.nodes[1])].position -
                                    m.nodes[static_cast<std::size_t>(element.nodes[0])].position)
                                       .normalized();
      const Vec3& X = m.nodes[static_cast<std::size_t>(node)].position;
      for (int k = 0; k < 6; ++k) {
        if (!(mask[static_cast<std::size_t>(node)] & (1u << k))) continue;
        const double value = k < 3 ? g.position[k] : g.slope[k - 3];
        const double reference = k < 3 ? X[k] : reference_slope[k - 3];
        if (std::abs(value - reference) > kFixedValueTolerance * (1.0 + s.back())) return none;
      }
      guess.push_back(g);
    }
  }
  return guess;
}

void set_guess(const assembly::SecondOrderSystem& system, const std::vector<NodeGuess>& guess,
               Vec q) {
  const assembly::DofMap& dofs = system.dof_map();
  PetscScalar* values = nullptr;
  CATENA_PETSC(VecGetArray(q, &values));
  const auto set = [&](int node, int k, double value) {
    const PetscInt g = dofs.global_dof(node, k);
    if (g >= dofs.first_owned() && g < dofs.first_owned() + dofs.n_owned() &&
        dofs.coefficient(node, k) == 1.0)
      values[g - dofs.first_owned()] = value;
  };
  for (const NodeGuess& g : guess) {
    const model::UnknownKindInfo& kind = model::kind_info(dofs.node_kind(g.node));
    for (int d = 0; d < 3; ++d) {
      set(g.node, kind.position + d, g.position[d]);
      if (kind.gradients >= 0) set(g.node, kind.gradients + d, g.slope[d]);
    }
  }
  CATENA_PETSC(VecRestoreArray(q, &values));
}

VecHandle hanging_cable_start(const assembly::SecondOrderSystem& system) {
  if (!system.model().static_options.elastic_catenary_guess) return VecHandle();
  const std::optional<std::vector<NodeGuess>> guess = hanging_cable_guess(system.model());
  if (!guess) return VecHandle();
  VecHandle q = system.create_vector();
  system.reference_state(q.get());
  set_guess(system, *guess, q.get());
  return q;
}

std::string describe_guess(GuessOutcome outcome) {
  switch (outcome) {
    case GuessOutcome::accepted:
      return "  started from each line's elastic catenary (closed form): the whole load in one "
             "step";
    case GuessOutcome::rejected:
      return "  each line's elastic catenary (closed form) did not converge as a start: "
             "stepped along the load path instead";
    case GuessOutcome::none:
      break;
  }
  return "";
}

}  // namespace catena::solvers
