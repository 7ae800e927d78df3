#include "catena/couplings/element_factory.hpp"

#include <span>
#include <type_traits>

#include "catena/elements/absorbing_end.hpp"
#include "catena/elements/ancf_beam.hpp"
#include "catena/elements/ancf_cable.hpp"
#include "catena/elements/linear_spring.hpp"
#include "catena/elements/point_mass.hpp"
#include "catena/elements/rayleigh_damped.hpp"
#include "catena/elements/rigid_body.hpp"
#include "catena/elements/surface_contact.hpp"
#include "catena/elements/tension_bar.hpp"

namespace catena::couplings {
namespace {

// The element's reference state: per node the first dofs_per_node() of
// [position, tangent, section_y, section_z], as SecondOrderSystem::reference_state.
std::vector<double> reference_state(const model::Model& model, std::span<const int> nodes,
                                    int dofs_per_node) {
  std::vector<double> q;
  for (int n : nodes) {
    const model::Node& node = model.nodes[n];
    const Vec3* parts[4] = {&node.position, &node.tangent, &node.section_y, &node.section_z};
    for (int k = 0; k < dofs_per_node; ++k) q.push_back((*parts[k / 3])[k % 3]);
  }
  return q;
}

// Rayleigh damping wraps the element when its section asks for it.
std::unique_ptr<elements::Element> with_rayleigh(std::unique_ptr<elements::Element> e,
                                                 const model::Rayleigh& r,
                                                 const model::Model& model,
                                                 std::span<const int> nodes,
                                                 std::shared_ptr<elements::MatrixArena> arena) {
  if (!r.active()) return e;
  const std::vector<double> q_ref = reference_state(model, nodes, e->dofs_per_node());
  return std::make_unique<elements::RayleighDamped>(
      std::move(e), elements::RayleighCoefficients{r.mass, r.stiffness}, q_ref, std::move(arena));
}

}  // namespace

std::unique_ptr<elements::Element> make_element(const model::Model& model, int index,
                                                std::shared_ptr<elements::MatrixArena> arena) {
  const model::ElementDesc& desc = model.elements[index];
  const Vec3& xa = model.nodes[desc.nodes[0]].position;
  const Vec3& xb = model.nodes[desc.nodes[1]].position;
  const double length = (xb - xa).norm();
  return std::visit(
      [&](const auto& p) -> std::unique_ptr<elements::Element> {
        using P = std::decay_t<decltype(p)>;
        if constexpr (std::is_same_v<P, model::CableProps>) {
          const elements::CableSection s{
              p.EA,        p.EI,           p.mass_per_length,      p.damping_time,
              p.prestrain, p.tension_only, p.prestrain_with_loads, p.curvature};
          return with_rayleigh(std::make_unique<elements::AncfCable>(length, s, model.gravity,
                                                                     desc.distributed_load),
                               p.rayleigh, model, desc.nodes, arena);
        } else if constexpr (std::is_same_v<P, model::BarProps>) {
          const elements::BarSection s{p.EA, p.mass_per_length, p.damping, p.tension_only};
          const double l0 = p.unstretched_length > 0.0 ? p.unstretched_length : length;
          return std::make_unique<elements::TensionBar>(l0, s, model.gravity, length);
        } else if constexpr (std::is_same_v<P, model::SpringProps>) {
          return std::make_unique<elements::LinearSpring>(
              xa, xb, elements::SpringSection{p.stiffness, p.damping});
        } else {
          static_assert(std::is_same_v<P, model::BeamProps>);
          auto node_ref = [&](int n) {
            const model::Node& node = model.nodes[n];
            return elements::BeamNodeRef{node.position, node.tangent, node.section_y,
                                         node.section_z};
          };
          const elements::BeamSection s{
              p.EA,     p.GA_y,   p.GA_z,         p.GJ,       p.EI_y, p.EI_z, p.mass_per_length,
              p.rho_Iy, p.rho_Iz, p.damping_time, p.curvature};
          return with_rayleigh(std::make_unique<elements::AncfBeam>(
                                   node_ref(desc.nodes[0]), node_ref(desc.nodes[1]), s,
                                   elements::BeamLoads{model.gravity, desc.distributed_load}),
                               p.rayleigh, model, desc.nodes, arena);
        }
      },
      *desc.props);
}

std::unique_ptr<ElementCoupling> make_element_coupling(const model::Model& model, int index,
                                                       std::unique_ptr<elements::Element> element) {
  const auto& nodes = model.elements[index].nodes;
  return std::make_unique<ElementCoupling>(std::move(element),
                                           std::vector<int>(nodes.begin(), nodes.end()),
                                           ElementOrigin::element, index);
}

std::vector<std::unique_ptr<ElementCoupling>> make_node_couplings(const model::Model& model) {
  std::vector<std::unique_ptr<ElementCoupling>> couplings;
  auto add = [&](std::unique_ptr<elements::Element> e, int node, ElementOrigin origin, int src) {
    couplings.push_back(
        std::make_unique<ElementCoupling>(std::move(e), std::vector<int>{node}, origin, src));
  };
  for (size_t i = 0; i < model.point_masses.size(); ++i) {
    const auto& m = model.point_masses[i];
    add(std::make_unique<elements::PointMass>(m.mass, model.gravity), m.node,
        ElementOrigin::point_mass, static_cast<int>(i));
  }
  for (size_t i = 0; i < model.rigid_bodies.size(); ++i) {
    const auto& b = model.rigid_bodies[i];
    add(std::make_unique<elements::RigidBodyInertia>(b.mass, b.centre_of_mass, b.inertia,
                                                     model.gravity),
        b.node, ElementOrigin::rigid_body, static_cast<int>(i));
  }
  for (size_t i = 0; i < model.elastic_supports.size(); ++i) {
    const auto& s = model.elastic_supports[i];
    add(std::make_unique<elements::GroundSpring>(model.nodes[s.node].position,
                                                 elements::SpringSection{s.stiffness, s.damping}),
        s.node, ElementOrigin::elastic_support, static_cast<int>(i));
  }
  // Without force or dashpot until assembly::SecondOrderSystem::calibrate_absorbing_ends.
  for (size_t i = 0; i < model.absorbing_ends.size(); ++i)
    add(std::make_unique<elements::AbsorbingEnd>(elements::AbsorbingEndLaw{}),
        model.absorbing_ends[i].node, ElementOrigin::absorbing_end, static_cast<int>(i));
  for (size_t i = 0; i < model.surfaces.size(); ++i) {
    const model::Surface& s = model.surfaces[i];
    const elements::SurfaceContactLaw law{s.point,   s.normal,   s.stiffness,
                                          s.damping, s.friction, s.stick_speed};
    for (const int node : s.nodes)
      add(std::make_unique<elements::SurfaceContact>(law), node, ElementOrigin::surface_contact,
          static_cast<int>(i));
  }
  for (size_t i = 0; i < model.nodal_loads.size(); ++i) {
    const auto& l = model.nodal_loads[i];
    add(std::make_unique<elements::NodalForce>(l.force), l.node, ElementOrigin::nodal_load,
        static_cast<int>(i));
  }
  return couplings;
}

}  // namespace catena::couplings
