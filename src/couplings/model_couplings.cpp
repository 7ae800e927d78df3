#include "catena/couplings/model_couplings.hpp"

#include "catena/couplings/bilateral_contact.hpp"
#include "catena/couplings/body_frame_constraint.hpp"
#include "catena/couplings/element_factory.hpp"
#include "catena/couplings/joint_constraint.hpp"
#include "catena/couplings/joint_spring.hpp"
#include "catena/couplings/moving_load.hpp"
#include "catena/couplings/node_constraint.hpp"
#include "catena/couplings/pantograph_contact.hpp"
#include "catena/couplings/slider_constraint.hpp"

namespace catena::couplings {

CouplingList make_couplings(const model::Model& model, const std::vector<int>& element_owner,
                            const std::vector<int>& node_owner, int rank) {
  CouplingList list;
  // The kernels first, then their couplings: each kind's objects then lie together in
  // memory in the order the assembly loop visits them, which the residual's speed depends
  // on (docs/performance.md, "Couplings loop against the hand-written assembly").
  // Their constant matrices in one arena, in the same order (elements/matrix_arena.hpp).
  std::vector<int> owned;
  std::vector<std::unique_ptr<elements::Element>> kernels;
  const auto arena = std::make_shared<elements::MatrixArena>();
  for (int e = 0; e < static_cast<int>(model.elements.size()); ++e)
    if (element_owner[static_cast<size_t>(e)] == rank) {
      owned.push_back(e);
      kernels.push_back(make_element(model, e, arena));
    }
  for (size_t k = 0; k < owned.size(); ++k)
    list.push_back(make_element_coupling(model, owned[k], std::move(kernels[k])));
  for (auto& c : make_node_couplings(model))
    if (node_owner[static_cast<size_t>(c->nodes().front())] == rank) list.push_back(std::move(c));
  for (const model::MovingLoad& load : model.moving_loads) {
    std::vector<bool> evaluated;
    bool any = false;
    for (int e : load.elements) {
      evaluated.push_back(element_owner[static_cast<size_t>(e)] == rank);
      any = any || evaluated.back();
    }
    if (any) list.push_back(std::make_unique<MovingLoad>(model, load, evaluated));
  }
  for (int c = 0; c < static_cast<int>(model.constraints.size()); ++c) {
    const model::Constraint& constraint = model.constraints[static_cast<size_t>(c)];
    if (node_owner[static_cast<size_t>(constraint.node_a)] != rank) continue;
    if (constraint.type == model::ConstraintType::frame_lengths ||
        constraint.type == model::ConstraintType::frame_angles)
      list.push_back(std::make_unique<BodyFrameConstraint>(model, c));
    else if (constraint.type == model::ConstraintType::joint)
      list.push_back(std::make_unique<JointConstraint>(model, c));
    else if (constraint.type == model::ConstraintType::slider)
      list.push_back(std::make_unique<SliderConstraint>(model, c));
    else if (constraint.type == model::ConstraintType::contact)
      list.push_back(std::make_unique<BilateralContact>(model, c));
    else
      list.push_back(std::make_unique<NodeConstraint>(model, c));
  }
  for (int j = 0; j < static_cast<int>(model.joints.size()); ++j) {
    const model::Joint& joint = model.joints[static_cast<size_t>(j)];
    const int node = model.rigid_bodies[static_cast<size_t>(joint.body_a)].node;
    if (joint.has_coordinate_force() && node_owner[static_cast<size_t>(node)] == rank)
      list.push_back(std::make_unique<JointSpring>(model, j));
  }
  for (int c = 0; c < static_cast<int>(model.contacts.size()); ++c) {
    const model::MovingContact& contact = model.contacts[static_cast<size_t>(c)];
    if (!contact.bilateral && node_owner[static_cast<size_t>(contact.head_node)] == rank)
      list.push_back(std::make_unique<PantographContact>(model, c));
  }
  return list;
}

}  // namespace catena::couplings
