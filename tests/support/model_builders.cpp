#include "model_builders.hpp"

#include <cmath>
#include <variant>
#include <vector>

namespace catena::test {

std::vector<int> add_line(model::Model& m, const Vec3& a, const Vec3& b, int n_elements,
                          const model::ElementProps& props) {
  std::vector<int> nodes;
  for (int i = 0; i <= n_elements; ++i) {
    model::Node node;
    node.position = a + (b - a) * (static_cast<double>(i) / n_elements);
    node.id = static_cast<std::int64_t>(m.nodes.size()) + 1;
    nodes.push_back(static_cast<int>(m.nodes.size()));
    m.nodes.push_back(node);
  }
  for (int i = 0; i < n_elements; ++i) {
    // Built in place: a local copied in made GCC 12 -O3 warn (maybe-uninitialized) about
    // the variant's copy.
    model::ElementDesc& e = m.elements.emplace_back();
    e.id = static_cast<std::int64_t>(m.elements.size());
    e.nodes = {nodes[i], nodes[i + 1]};
    e.props = props;
  }
  return nodes;
}

void set_reference_frames(model::Model& m) {
  for (const auto& e : m.elements) {
    const bool has_slope = std::holds_alternative<model::CableProps>(*e.props) ||
                           std::holds_alternative<model::BeamProps>(*e.props);
    if (!has_slope) continue;
    const Vec3 t = (m.nodes[e.nodes[1]].position - m.nodes[e.nodes[0]].position).normalized();
    for (int n : e.nodes) m.nodes[n].tangent = t;
    if (const auto* beam = std::get_if<model::BeamProps>(&*e.props)) {
      const Vec3 y = (beam->y_axis - beam->y_axis.dot(t) * t).normalized();
      for (int n : e.nodes) {
        m.nodes[n].section_y = y;
        m.nodes[n].section_z = t.cross(y);
      }
    }
  }
}

void pin(model::Model& m, int node) { m.supports.push_back({node, 0x7u}); }
void clamp(model::Model& m, int node) { m.supports.push_back({node, 0xFFFu}); }

void clamp_direction(model::Model& m, int node) { m.supports.push_back({node, 0xFC7u, true}); }

model::Model cable_pendulum(int n_elements, bool driven_pivot) {
  model::Model m;
  m.gravity = Vec3(0, 0, -9.81);
  model::CableProps cable;
  cable.EA = 1260.0;
  cable.EI = 8.505e-3;
  cable.mass_per_length = 9.972;
  const std::vector<int> nodes = add_line(m, {0, 0, 0}, {1.2, 0, 0}, n_elements, cable);
  set_reference_frames(m);
  if (!driven_pivot) {
    pin(m, nodes.front());
    return m;
  }
  model::Constraint c;
  c.node_a = nodes.front();
  c.type = model::ConstraintType::prescribed;
  c.amplitude = Vec3(0.05, 0, 0);
  c.frequency = 2.0;
  c.velocity = Vec3(-2.0 * M_PI * 2.0 * 0.05, 0, 0);
  m.constraints.push_back(c);
  return m;
}

std::string pantograph_on_wire_scene(double start) {
  return R"(
sections:
  cw: {type: cable, EA: 1.8e7, EI: 195, mass_per_length: 1.35}
nodes:
  - {id: 1, position: [0, 0, 0]}
  - {id: 2, position: [30, 0, 0]}
lines:
  - {name: cw, from: 1, to: 2, elements: 60, section: cw, tension: 20000}
supports:
  - {node: 1, fix: pinned}
  - {node: 2, fix: pinned}
pantographs:
  - {name: p, line: cw, speed: 60, start: )" +
         std::to_string(start) + R"(, static_force: 120, model: en50318}
analysis: {type: dynamic, duration: 1.0}
)";
}

model::Model cable_line_with_items(const model::CableProps& section, double support_damping) {
  model::Model m;
  m.gravity = Vec3(0, 0, -9.81);
  const int n = 24;
  const auto nodes = add_line(m, {0, 0, 0}, {60, 0, 0}, n, section);
  for (int i = 4; i < n; i += 4) m.point_masses.push_back({nodes[i], 0.195});
  set_reference_frames(m);
  pin(m, nodes.front());
  pin(m, nodes.back());
  m.elastic_supports.push_back(
      {nodes[n / 2], Vec3(0, 300, 300), Vec3(0, support_damping, support_damping)});
  return m;
}

}  // namespace catena::test
