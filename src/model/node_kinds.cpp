#include "catena/model/node_kinds.hpp"

#include <optional>
#include <string>
#include <type_traits>

#include "catena/core/error.hpp"

namespace catena::model {
namespace {

std::string element_text(const ElementDesc& e) {
  return std::visit([](const auto& p) { return std::string(std::decay_t<decltype(p)>::kind); },
                    *e.props) +
         " element " + std::to_string(e.id);
}

}  // namespace

UnknownKind element_node_kind(const ElementProps& props) {
  return std::visit([](const auto& p) { return std::decay_t<decltype(p)>::node_kind; }, props);
}

int element_node_dofs(const ElementProps& props) {
  return kind_info(element_node_kind(props)).size;
}

std::vector<UnknownKind> node_kinds(const Model& model) {
  std::vector<UnknownKind> kinds(model.nodes.size(), UnknownKind::point);
  std::vector<int> decided_by(model.nodes.size(), -1);  // element that set the kind
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    const ElementDesc& element = model.elements[e];
    const UnknownKind asked = element_node_kind(*element.props);
    for (const int node : element.nodes) {
      const std::optional<UnknownKind> both = kind_holding_both(kinds[node], asked);
      if (!both)
        throw Error("node " + std::to_string(model.nodes[node].id) + " joins " +
                    (decided_by[node] >= 0 ? element_text(model.elements[decided_by[node]])
                                           : std::string("its own position")) +
                    " (" + std::string(kind_info(kinds[node]).name) + ") and " +
                    element_text(element) + " (" + std::string(kind_info(asked).name) +
                    "), whose unknowns no node kind holds together; connect them through a "
                    "constraint or a spring instead");
      if (*both != kinds[node]) decided_by[node] = static_cast<int>(e);
      kinds[node] = *both;
    }
  }
  for (const RigidBody& body : model.rigid_bodies) {
    const int node = body.node;
    if (!kind_holding_both(kinds[node], UnknownKind::rigid_body))
      throw Error("node " + std::to_string(model.nodes[node].id) + " carries rigid body '" +
                  body.name + "' and " + element_text(model.elements[decided_by[node]]) + " (" +
                  std::string(kind_info(kinds[node]).name) +
                  "); a body's node takes bars, springs and masses only: join a cable or beam "
                  "to the body through a constraint at another node");
    kinds[node] = UnknownKind::rigid_body;
  }
  for (const Slider& slider : model.sliders) {
    const int node = slider.node;
    if (!kind_holding_both(kinds[node], UnknownKind::slider))
      throw Error("node " + std::to_string(model.nodes[node].id) + " carries slider '" +
                  slider.name + "' and is " + std::string(kind_info(kinds[node]).name) +
                  "; a slider's node takes bars, springs, masses and spherical joints only: "
                  "give the slider a node of its own");
    kinds[node] = UnknownKind::slider;
  }
  return kinds;
}

std::vector<int> all_node_dofs(const Model& model) {
  const std::vector<UnknownKind> kinds = node_kinds(model);
  std::vector<int> dofs(kinds.size());
  for (std::size_t n = 0; n < kinds.size(); ++n) dofs[n] = kind_info(kinds[n]).size;
  return dofs;
}

}  // namespace catena::model
