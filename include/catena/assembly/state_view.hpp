#pragma once
// What output, checkpoints and tests ask of a state of the SecondOrderSystem: node values,
// section results, support reactions, contact states, constraint forces and the
// node-indexed (partition-independent) rows a checkpoint stores. A view holds no data of
// its own and may be made wherever it is needed: StateView(system).contact_states(p).
// Kept apart from the system so that the system's interface is what solvers use
// (residuals, matrices, patches) and a new output field touches this file, not that one.
#include <petscvec.h>

#include <vector>

#include "catena/assembly/second_order_system.hpp"
#include "catena/elements/element.hpp"

namespace catena::assembly {

// Per supported node (owned by this rank): reaction of the supports on the node.
struct Reactions {
  std::vector<int> nodes;      // ascending model node indices
  std::vector<double> force;   // 3 per node, N
  std::vector<double> moment;  // 3 per node, N·m (from fixed slope DOFs)
};

// A moving contact (model::MovingContact, a pantograph head on a wire) at a state.
struct ContactState {
  double force = 0.0;        // N, ≥ 0 (0: no contact); a bilateral contact may be < 0
  double position = 0.0;     // m along the path (the pantograph's position)
  double penetration = 0.0;  // m, (r_head − r_wire)·up; > 0 in contact (bilateral: 0)
  bool on_path = false;      // the contact point is on its path
};

// Every rigid body's pose and angular velocity at a state (model::RigidBody order;
// identical on every rank).
struct BodyPoses {
  // Unit quaternions (w, x, y, z), 4 per body, of the rotation R = [e1 e2 e3] from the body
  // axes to the global frame (the nearest rotation: R is orthonormal to the Newton
  // tolerance only).
  std::vector<double> orientation;
  std::vector<double> angular_velocity;  // rad/s, 3 per body: ω = ½ Σ e_k × ė_k
};

// Every slider's arc length along its path and its rate (model::Slider order; identical on
// every rank).
struct SliderTravel {
  std::vector<double> position;  // m
  std::vector<double> speed;     // m/s
};

class StateView {
 public:
  explicit StateView(const SecondOrderSystem& system);

  // Collective. Every contact's state at p (identical on every rank).
  std::vector<ContactState> contact_states(const EvalPoint& p) const;
  // Collective. Section results for this rank's model elements (ascending index).
  void section_results(const EvalPoint& p, std::vector<int>& elements,
                       std::vector<elements::SectionResult>& results) const;
  // Collective. Full nodal values (fixed DOFs included) of owned nodes: positions and
  // slopes (∂r/∂x, zero where a node has none), 3 each.
  void owned_node_values(Vec q, std::vector<double>& positions, std::vector<double>& slopes) const;
  // Collective. The same for a change of state dq (a mode shape, a velocity): the fixed
  // DOFs do not change, so they read 0 instead of their reference values.
  void owned_node_changes(Vec dq, std::vector<double>& positions,
                          std::vector<double>& slopes) const;
  // Collective. Support reactions at owned supported nodes.
  Reactions reactions(const EvalPoint& p) const;
  // Collective. Every rigid body's orientation and angular velocity at (q, v).
  BodyPoses body_poses(Vec q, Vec v) const;
  // Collective. Every slider's s and ṡ at (q, v).
  SliderTravel slider_travel(Vec q, Vec v) const;
  // Collective. Every joint's two links at q, for drawing the mechanism (model::Joint order;
  // identical on every rank): 12 values per joint, the points [A's node, the joint's point
  // carried by A, the joint's point carried by B, B's node] (m, global). B the ground: its
  // point and node both the joint's reference point; B a node (a spherical joint): both
  // that node's position. The two carried points coincide to the Newton tolerance where the
  // joint holds them together (spherical, revolute, fixed); along the axis they part by
  // the slide of a prismatic or cylindrical joint.
  std::vector<double> joint_links(Vec q) const;
  // Not collective. This rank's constraints (ascending index) and the force each applies
  // to its node A, −λ (model::multiplier_width values per constraint, padded with 0; N for a
  // node constraint), from the multiplier slots of q.
  void owned_constraint_forces(Vec q, std::vector<int>& constraints,
                               std::vector<double>& forces) const;

  // Not collective. Where one component (0 x, 1 y, 2 z) of the position of each of `nodes`
  // owned here lies in a state vector: `slot` the node's place in `nodes`, `row` its local
  // row in the vector's owned part (−1 for a fixed DOF, whose value is `fixed`), the value
  // the DOF's `coefficient` times the row's entry. For a few nodes every step (the
  // registration points' heights), without gathering every node as owned_node_values does.
  struct ComponentRows {
    std::vector<int> slot;
    std::vector<PetscInt> row;
    std::vector<double> coefficient, fixed;
  };
  ComponentRows position_rows(const std::vector<int>& nodes, int component) const;

  // Not collective. x's free DOFs of the owned nodes in their kinds' layouts, padded to
  // model::kMaxBlockUnknowns values per node of dof_map().owned_nodes() (fixed and absent
  // components 0), and this rank's
  // multiplier slots (model::multiplier_width per owned constraint, ascending, padded with
  // 0): a partition-independent form.
  void owned_node_rows(Vec x, std::vector<double>& rows, std::vector<double>& multipliers) const;
  // Not collective. The inverse for every node and constraint at once: x's owned free DOFs
  // from rows (kMaxBlockUnknowns per node, all nodes) and its owned multiplier slots from
  // multipliers (model::multiplier_width per constraint, all constraints).
  void set_from_node_rows(Vec x, const std::vector<double>& rows,
                          const std::vector<double>& multipliers) const;

 private:
  void gather_owned_nodes(Vec q, std::vector<double>& positions, std::vector<double>& slopes,
                          bool fixed_at_reference) const;
  const SecondOrderSystem& system_;
  // The couplings that are pantograph contacts, found once: contact_states runs every step,
  // and a type test of every coupling there cost more than the contacts themselves.
  std::vector<size_t> contact_couplings_;    // penalty contacts (PantographContact)
  std::vector<size_t> bilateral_couplings_;  // bilateral ones (BilateralContact)
};

}  // namespace catena::assembly
