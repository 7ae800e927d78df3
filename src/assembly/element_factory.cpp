#include "catena/assembly/element_factory.hpp"

#include <type_traits>


#include "catena/elements/ancf_beam.hpp"
#include "catena/elements/ancf_cable.hpp"
#include "catena/elements/linear_spring.hpp"
#include "catena/elements/point_mass.hpp"
#include "catena/elements/tension_bar.hpp"

namespace catena::assembly {

Kernel make_element_kernel(const model::Model& model, int index) {
  const model::ElementDesc& desc = model.elements[index];
  const Vec3& xa = model.nodes[desc.nodes[0]].position;
  const Vec3& xb = model.nodes[desc.nodes[1]].position;
  const double length = (xb - xa).norm();
  Kernel k;
  k.nodes = desc.nodes;
  k.origin = KernelOrigin::element;
  k.source = index;
  k.element = std::visit(
      [&](const auto& p) -> std::unique_ptr<elements::Element> {
        using P = std::decay_t<decltype(p)>;
        if constexpr (std::is_same_v<P, model::CableProps>) {
          const elements::CableSection s{p.EA, p.EI, p.mass_per_length, p.damping_time,
                                         p.prestrain};
          return std::make_unique<elements::AncfCable>(length, s, model.gravity,
                                                       desc.distributed_load);
        } else if constexpr (std::is_same_v<P, model::BarProps>) {
          const elements::BarSection s{p.EA, p.mass_per_length, p.damping, p.tension_only};
          const double l0 = p.unstretched_length > 0.0 ? p.unstretched_length : length;
          return std::make_unique<elements::TensionBar>(l0, s, model.gravity, length);
        } else if constexpr (std::is_same_v<P, model::SpringProps>) {
          return std::make_unique<elements::LinearSpring>(xa, xb,
                                                          elements::SpringSection{p.stiffness, p.damping});
        } else {
          static_assert(std::is_same_v<P, model::BeamProps>);
          auto node_ref = [&](int n) {
            const model::Node& node = model.nodes[n];
            return elements::BeamNodeRef{node.position, node.tangent, node.section_y,
                                         node.section_z};
          };
          const elements::BeamSection s{p.EA,   p.GA_y, p.GA_z,   p.GJ,     p.EI_y,
                                        p.EI_z, p.mass_per_length, p.rho_Iy, p.rho_Iz,
                                        p.damping_time};
          return std::make_unique<elements::AncfBeam>(
              node_ref(desc.nodes[0]), node_ref(desc.nodes[1]), s,
              elements::BeamLoads{model.gravity, desc.distributed_load});
        }
      },
      desc.props);
  return k;
}

std::vector<Kernel> make_node_kernels(const model::Model& model) {
  std::vector<Kernel> kernels;
  auto add = [&](std::unique_ptr<elements::Element> e, int node, KernelOrigin origin, int src) {
    Kernel k;
    k.element = std::move(e);
    k.nodes = {node};
    k.origin = origin;
    k.source = src;
    kernels.push_back(std::move(k));
  };
  for (size_t i = 0; i < model.point_masses.size(); ++i) {
    const auto& m = model.point_masses[i];
    add(std::make_unique<elements::PointMass>(m.mass, model.gravity), m.node,
        KernelOrigin::point_mass, static_cast<int>(i));
  }
  for (size_t i = 0; i < model.elastic_supports.size(); ++i) {
    const auto& s = model.elastic_supports[i];
    add(std::make_unique<elements::GroundSpring>(model.nodes[s.node].position,
                                                 elements::SpringSection{s.stiffness, s.damping}),
        s.node, KernelOrigin::elastic_support, static_cast<int>(i));
  }
  for (size_t i = 0; i < model.nodal_loads.size(); ++i) {
    const auto& l = model.nodal_loads[i];
    add(std::make_unique<elements::NodalForce>(l.force), l.node, KernelOrigin::nodal_load,
        static_cast<int>(i));
  }
  return kernels;
}

}  // namespace catena::assembly
