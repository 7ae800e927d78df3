#pragma once
// An element kernel (elements/element.hpp) as a coupling: it acts on every DOF of its nodes
// (node-major, the first dofs_per_node() of each node's layout), densely.
// Node-attached items (point masses, elastic supports, nodal loads) are one-node elements,
// so that assembly has a single loop; `origin` says which model item a coupling came from.
#include <memory>
#include <vector>

#include "catena/couplings/coupling.hpp"
#include "catena/elements/element.hpp"

namespace catena::couplings {

enum class ElementOrigin {
  element,
  point_mass,
  rigid_body,
  elastic_support,
  surface_contact,
  nodal_load,
  absorbing_end
};

// Whether an item of this origin acts as a support: its force on its node is a reaction
// (an elastic support, a surface, an absorbing end; StateView::reactions).
inline bool acts_as_support(ElementOrigin origin) {
  return origin == ElementOrigin::elastic_support || origin == ElementOrigin::surface_contact ||
         origin == ElementOrigin::absorbing_end;
}

class ElementCoupling final : public Coupling {
 public:
  // `source` indexes the model vector named by `origin`.
  ElementCoupling(std::unique_ptr<elements::Element> element, std::vector<int> nodes,
                  ElementOrigin origin, int source);

  void evaluate(const CouplingState& s, double* f, std::span<const MatrixRequest> m,
                Scratch& scratch) const override;
  bool has_damping() const override { return element_->has_damping(); }
  bool in_force_scale() const override { return true; }
  PatchRole patch_role() const override { return PatchRole::kernel; }

  const elements::Element& element() const { return *element_; }
  // Not collective. From now on the element linearised about its local state q0
  // (elements/linearized.hpp): constant stiffness and damping, force f0 + K0 Δq + C0 v.
  void linearize_about(std::span<const double> q0);
  // Not collective. From now on `element` in place of the present one, on the same nodes
  // and DOFs (asserted): an absorbing end's law, known once the run's initial state is.
  void replace_element(std::unique_ptr<elements::Element> element);
  const std::vector<int>& nodes() const { return nodes_; }
  ElementOrigin origin() const { return origin_; }
  int source() const { return source_; }

 private:
  std::unique_ptr<elements::Element> element_;
  std::vector<int> nodes_;  // model node indices
  ElementOrigin origin_;
  int source_;
};

}  // namespace catena::couplings
