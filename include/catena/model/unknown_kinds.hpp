#pragma once
// The kinds of unknowns Catena numbers, in one table.
//
// Every block of unknowns has a kind: a node's block (its kind set by the elements attached
// to it, model/node_kinds.hpp) and a constraint's Lagrange multipliers. Everything that
// walks unknowns asks this table instead of assuming a layout:
//   - the numbering (assembly/dof_map: how many unknowns a block has, in which order),
//   - supports (model/attachment_reader: which components a node has, by name),
//   - messages naming an unknown ("node 17 (rx_z)": SecondOrderSystem::describe_dof),
//   - output and reactions (assembly/state_view: where the position and the gradients are),
//   - reference coordinates (assembly/second_order_system: the same slots),
//   - checkpoints (rows of kMaxBlockUnknowns per node, io/checkpoint),
//   - the integrators' state update (`update`, checked by solvers/time/integrator_factory).
// A new kind (a modal block, a slider coordinate) is a new row
// here; a `switch` over UnknownKind or UpdateRule has no `default:`, so a kind or rule some
// code does not handle is a compile error (-Wswitch), not a silent fallback.
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace catena::model {

// The widest block (an ANCF beam node: r, r_x, r_y, r_z). Checkpoint rows have this width.
inline constexpr int kMaxBlockUnknowns = 12;

// The most multipliers one constraint has (model::Constraint::equations: a fixed joint's
// six).
inline constexpr int kMaxMultipliersPerConstraint = 6;

enum class UnknownKind : std::uint8_t {
  point,       // [x, y, z]: a node only bars, springs, point masses or supports touch
  ancf_cable,  // [r, r_x]: a node of gradient-deficient ANCF cables
  ancf_beam,   // [r, r_x, r_y, r_z]: a node of full-gradient ANCF beams
  // [r, e1, e2, e3]: a rigid body's point and axes (natural coordinates, model::RigidBody);
  // bars, springs and masses at its node act on r
  rigid_body,
  // [x, y, z, s]: a slider's point and its arc length s along the cable or beam path it runs
  // on (model::Slider); bars, springs, masses and spherical joints at its node act on x, y, z
  slider,
  // [λ1 … λn]: the Lagrange multipliers of one constraint, n = Constraint::equations (a
  // position constraint's three are along x, y, z); the row is as wide as the widest
  multiplier,
};

// How an integrator moves a block's unknowns by an increment Δ. Every kind so far is
// additive (q ← q + Δ, also for the ANCF slopes, which are vectors, not rotations). A
// rotation parameterised by a unit quaternion would need q ← q ⊗ exp(Δ/2) and its own
// velocity map; the integrators implement only `additive` and refuse a model with any
// other (solvers/time/integrator_factory.cpp).
enum class UpdateRule : std::uint8_t { additive };

struct UnknownKindInfo {
  std::string_view name;     // in messages: "a cable node"
  std::string_view label;    // in summaries: "cable"
  std::string_view used_by;  // in messages: who gives a node this kind
  int size;                  // unknowns in a block of this kind (<= kMaxBlockUnknowns)
  // Component names, the first `size` used; supports (`fix: [rx_z]`) and messages use them.
  std::array<std::string_view, kMaxBlockUnknowns> components;
  int position;  // first component of the block's position (x, y, z), or −1
  // First component of the ANCF gradient vectors (r_x, then r_y and r_z on a beam node),
  // which run in threes to the block's end; −1 if none. The first is the slope (tangent).
  int gradients;
  UpdateRule update;
  bool nodal;  // a node's block (false: a constraint's multipliers)
};

// Not collective. The row of `kind`.
const UnknownKindInfo& kind_info(UnknownKind kind);
// Not collective. Every kind, in the table's order.
const std::vector<UnknownKind>& all_unknown_kinds();

// Not collective. The kind of a block that must hold both `a` and `b` (a node where
// elements of two kinds meet): the one whose components begin with all of the other's
// (a cable node holds a point's x, y, z; a beam node holds a cable node's r, r_x). None if
// neither does (the caller names the node and the elements in its error).
std::optional<UnknownKind> kind_holding_both(UnknownKind a, UnknownKind b);

}  // namespace catena::model
