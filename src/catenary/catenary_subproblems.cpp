#include "catenary_subproblems.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "catena/core/error.hpp"
#include "static_snapshot.hpp"

namespace catena::catenary::detail {
namespace {

constexpr unsigned kFixPosition = 0b111u;  // x, y, z
constexpr int kMaxTensionSolves = 8;

// A wire of a part: its cable elements (indices in the part), section and design tension.
struct PartWire {
  std::vector<int> cables;
  double EA = 0.0;         // N
  double tension = 0.0;    // N
  bool ends_move = false;  // a stitch wire: its sag strain is measured (sag_strain)
};

// Wires of the catenary as a model of their own: their cables and the joints between their
// nodes (staggered supports, stitch-wire ends), with the supports, elastic supports, point
// masses and nodal loads on those nodes (not the steady-arm preloads: they are what shape
// finding sizes).
struct WirePart {
  model::Model model;
  std::vector<int> part_node;   // per model node: its index in the part, −1 if absent
  std::vector<PartWire> wires;  // in the order extracted
};

// `stitch_from`: the wires from this position on are stitch wires.
WirePart extract_wires(const model::Model& m, const std::vector<const model::CatenaryWire*>& wires,
                       std::size_t stitch_from) {
  WirePart part;
  part.model.name = m.name + " (" + wires.front()->name +
                    (wires.size() > 1 ? " with the stitch wires" : "") + " alone)";
  part.model.gravity = m.gravity;
  part.model.static_options = m.static_options;
  part.part_node.assign(m.nodes.size(), -1);
  const auto add_node = [&](int node) {
    int& index = part.part_node[static_cast<std::size_t>(node)];
    if (index >= 0) return;
    index = static_cast<int>(part.model.nodes.size());
    part.model.nodes.push_back(m.nodes[static_cast<std::size_t>(node)]);
  };
  const auto remap = [&](model::ElementDesc element) {
    for (int& node : element.nodes) node = part.part_node[static_cast<std::size_t>(node)];
    return element;
  };
  for (const model::CatenaryWire* wire : wires)
    for (const int e : wire->elements)
      for (const int node : m.elements[static_cast<std::size_t>(e)].nodes) add_node(node);
  for (const model::CatenaryWire* wire : wires) {
    PartWire w;
    w.tension = wire->tension;
    w.ends_move = part.wires.size() >= stitch_from;
    for (const int e : wire->elements) {
      w.cables.push_back(static_cast<int>(part.model.elements.size()));
      part.model.elements.push_back(remap(m.elements[static_cast<std::size_t>(e)]));
    }
    w.EA = std::get<model::CableProps>(
               *part.model.elements[static_cast<std::size_t>(w.cables.front())].props)
               .EA;
    part.wires.push_back(std::move(w));
  }
  const auto in_part = [&](int node) {
    return part.part_node[static_cast<std::size_t>(node)] >= 0;
  };
  for (const model::ElementDesc& element : m.elements)
    if (std::holds_alternative<model::SpringProps>(*element.props) &&
        std::all_of(element.nodes.begin(), element.nodes.end(), in_part))
      part.model.elements.push_back(remap(element));
  for (model::Support s : m.supports)
    if (in_part(s.node)) {
      s.node = part.part_node[static_cast<std::size_t>(s.node)];
      part.model.supports.push_back(s);
    }
  for (model::ElasticSupport s : m.elastic_supports)
    if (in_part(s.node)) {
      s.node = part.part_node[static_cast<std::size_t>(s.node)];
      part.model.elastic_supports.push_back(s);
    }
  for (model::PointMass p : m.point_masses)
    if (in_part(p.node)) {
      p.node = part.part_node[static_cast<std::size_t>(p.node)];
      part.model.point_masses.push_back(p);
    }
  std::vector<bool> preload(m.nodal_loads.size(), false);
  for (const model::CatenaryRegistration& r : m.catenary->registrations)
    if (r.load >= 0) preload[static_cast<std::size_t>(r.load)] = true;
  for (std::size_t i = 0; i < m.nodal_loads.size(); ++i) {
    model::NodalLoad l = m.nodal_loads[i];
    if (preload[i] || !in_part(l.node)) continue;
    l.node = part.part_node[static_cast<std::size_t>(l.node)];
    part.model.nodal_loads.push_back(l);
  }
  return part;
}

void set_prestrain(WirePart& part, const PartWire& wire, double prestrain) {
  model::edit_shared(part.model.elements, wire.cables, [prestrain](model::ElementProps& p) {
    std::get<model::CableProps>(p).prestrain = prestrain;
  });
}

double prestrain_of(const WirePart& part, const PartWire& wire) {
  return std::get<model::CableProps>(
             *part.model.elements[static_cast<std::size_t>(wire.cables.front())].props)
      .prestrain;
}

// Solves the part, correcting each wire's prestrain until its mean axial force is its
// tension within tension_rtol (at most kMaxTensionSolves solves). Only the wires that are
// off are corrected, as in the whole-structure iteration.
StaticSnapshot solve_at_tension(MPI_Comm comm, WirePart& part, double tension_rtol, int& n_solves) {
  for (const PartWire& w : part.wires) set_prestrain(part, w, w.tension / w.EA);
  for (int k = 0;; ++k) {
    StaticSnapshot snapshot = solve_static_snapshot(comm, part.model);
    ++n_solves;
    bool converged = true;
    std::vector<double> next;
    for (const PartWire& w : part.wires) {
      const double mean = mean_axial_force(part.model, snapshot, w.cables);
      const double prestrain = prestrain_of(part, w);
      const bool off = std::abs(mean - w.tension) > tension_rtol * w.tension;
      converged = converged && !off;
      const double sag =
          w.ends_move ? sag_strain(part.model, snapshot, w.cables) : mean / w.EA - prestrain;
      next.push_back(off ? corrected_prestrain(prestrain, mean, w.tension, w.EA, sag) : prestrain);
    }
    if (converged || k + 1 == kMaxTensionSolves) return snapshot;
    for (std::size_t i = 0; i < part.wires.size(); ++i) set_prestrain(part, part.wires[i], next[i]);
  }
}

// The contact wire's nodes in path order (both nodes of a joint where a staggered wire is
// split at a support).
std::vector<int> nodes_in_order(const model::Model& m, const std::vector<int>& elements) {
  std::vector<int> order;
  for (const int e : elements) {
    const auto& nodes = m.elements[static_cast<std::size_t>(e)].nodes;
    if (order.empty() || order.back() != nodes[0]) order.push_back(nodes[0]);
    order.push_back(nodes[1]);
  }
  return order;
}

// Moves the part's contact-wire nodes onto the design polyline: heights given at `key`
// nodes (model indices), linear in x between them; nodal tangents follow the polyline.
void place_on_design_polyline(const model::Model& m, const std::vector<int>& order,
                              const std::map<int, double>& key, WirePart& part) {
  std::size_t previous_key = 0;  // position in `order`
  for (std::size_t i = 1; i < order.size(); ++i) {
    const auto next = key.find(order[i]);
    if (next == key.end()) continue;
    const double x0 = m.nodes[static_cast<std::size_t>(order[previous_key])].position.x();
    const double z0 = key.at(order[previous_key]);
    const double x1 = m.nodes[static_cast<std::size_t>(order[i])].position.x();
    for (std::size_t j = previous_key; j <= i; ++j) {
      const Vec3& reference = m.nodes[static_cast<std::size_t>(order[j])].position;
      const double t = x1 > x0 ? (reference.x() - x0) / (x1 - x0) : 0.0;
      part.model.nodes[static_cast<std::size_t>(part.part_node[static_cast<std::size_t>(order[j])])]
          .position.z() = z0 + t * (next->second - z0);
    }
    previous_key = i;
  }
  // A node's tangent is the mean direction of its cables (kinks only at held nodes).
  for (model::Node& node : part.model.nodes) node.tangent = Vec3::Zero();
  for (const int e : part.wires.front().cables) {
    const model::ElementDesc& element = part.model.elements[static_cast<std::size_t>(e)];
    model::Node& a = part.model.nodes[static_cast<std::size_t>(element.nodes[0])];
    model::Node& b = part.model.nodes[static_cast<std::size_t>(element.nodes[1])];
    const Vec3 direction = (b.position - a.position).normalized();
    a.tangent += direction;
    b.tangent += direction;
  }
  for (model::Node& node : part.model.nodes)
    if (node.tangent.norm() > 0.0) node.tangent.normalize();
}

// Adds kFixPosition to the support of part node `node` (creating it if needed).
void hold_position(WirePart& part, int node) {
  for (model::Support& s : part.model.supports)
    if (s.node == node) {
      s.fixed_mask |= kFixPosition;
      return;
    }
  part.model.supports.push_back(model::Support{node, kFixPosition});
}

}  // namespace

double corrected_prestrain(double prestrain, double mean_force, double tension, double EA,
                           double sag_strain) {
  const double sag = std::max(sag_strain, 0.0);
  const double slope = EA / (1.0 + 2.0 * EA * sag / std::max(mean_force, 1e-12 * EA));
  return prestrain + (tension - mean_force) / slope;
}

double corrected_prestrain(double prestrain, double mean_force, double tension, double EA) {
  return corrected_prestrain(prestrain, mean_force, tension, EA, mean_force / EA - prestrain);
}

double sag_strain(const model::Model& model, const StaticSnapshot& snapshot,
                  const std::vector<int>& cables) {
  double deformed = 0.0, reference = 0.0;
  const auto node = [&](int e, std::size_t k) {
    return static_cast<std::size_t>(model.elements[static_cast<std::size_t>(e)].nodes[k]);
  };
  for (const int e : cables) {
    deformed += (snapshot.positions[node(e, 1)] - snapshot.positions[node(e, 0)]).norm();
    reference += (model.nodes[node(e, 1)].position - model.nodes[node(e, 0)].position).norm();
  }
  const double chord =
      (snapshot.positions[node(cables.back(), 1)] - snapshot.positions[node(cables.front(), 0)])
          .norm();
  return (deformed - chord) / reference;
}

ContactWireLoads solve_contact_wire_held(MPI_Comm comm, const model::Model& model,
                                         const std::vector<double>& dropper_weight,
                                         double tension_rtol) {
  const model::CatenaryLayout& layout = *model.catenary;
  WirePart part = extract_wires(model, {&layout.contact_wire}, 1);
  const std::vector<int> order = nodes_in_order(model, layout.contact_wire.elements);
  std::map<int, double> key{
      {order.front(), model.nodes[static_cast<std::size_t>(order.front())].position.z()},
      {order.back(), model.nodes[static_cast<std::size_t>(order.back())].position.z()}};
  for (const model::CatenaryDropper& d : layout.droppers) key[d.contact_node] = d.design_z;
  // Every registration is on the polyline at its design height (the rest position of its
  // elastic support); held ones are also fixed there.
  for (const model::CatenaryRegistration& r : layout.registrations) key[r.node] = r.design_z;
  place_on_design_polyline(model, order, key, part);

  for (std::size_t i = 0; i < layout.droppers.size(); ++i) {
    const int node = part.part_node[static_cast<std::size_t>(layout.droppers[i].contact_node)];
    hold_position(part, node);
    part.model.nodal_loads.push_back(model::NodalLoad{node, Vec3(0.0, 0.0, -dropper_weight[i])});
  }
  for (const model::CatenaryRegistration& r : layout.registrations)
    if (r.load >= 0) hold_position(part, part.part_node[static_cast<std::size_t>(r.node)]);

  ContactWireLoads loads;
  const StaticSnapshot snapshot = solve_at_tension(comm, part, tension_rtol, loads.n_solves);
  const auto upward_reaction = [&](int model_node) {
    return snapshot
        .reactions[static_cast<std::size_t>(part.part_node[static_cast<std::size_t>(model_node)])]
        .z();
  };
  for (const model::CatenaryDropper& d : layout.droppers)
    loads.dropper_force.push_back(upward_reaction(d.contact_node));
  for (const model::CatenaryRegistration& r : layout.registrations)
    loads.registration_force.push_back(r.load >= 0 ? upward_reaction(r.node) : 0.0);
  return loads;
}

MessengerShape solve_messenger_loaded(MPI_Comm comm, const model::Model& model,
                                      const std::vector<double>& dropper_force,
                                      const std::vector<double>& dropper_weight,
                                      double tension_rtol) {
  const model::CatenaryLayout& layout = *model.catenary;
  std::vector<const model::CatenaryWire*> wires{&layout.messenger};
  for (const model::CatenaryStitch& stitch : layout.stitch_wires) wires.push_back(&stitch.wire);
  WirePart part = extract_wires(model, wires, 1);
  for (std::size_t i = 0; i < layout.droppers.size(); ++i) {
    const int node = part.part_node[static_cast<std::size_t>(layout.droppers[i].upper_node)];
    part.model.nodal_loads.push_back(
        model::NodalLoad{node, Vec3(0.0, 0.0, -(dropper_force[i] + dropper_weight[i]))});
  }
  MessengerShape shape;
  const StaticSnapshot snapshot = solve_at_tension(comm, part, tension_rtol, shape.n_solves);
  for (const model::CatenaryDropper& d : layout.droppers)
    shape.dropper_top.push_back(snapshot.positions[static_cast<std::size_t>(
        part.part_node[static_cast<std::size_t>(d.upper_node)])]);
  shape.prestrain = prestrain_of(part, part.wires.front());
  for (std::size_t k = 1; k < part.wires.size(); ++k)
    shape.stitch_prestrains.push_back(prestrain_of(part, part.wires[k]));
  return shape;
}

}  // namespace catena::catenary::detail
