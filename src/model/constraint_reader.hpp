#pragma once
// `constraints`: kinematic constraints enforced by Lagrange multipliers (model::Constraint):
//   - {type: coincident, nodes: [A, B]}       r_A = r_B (a clamp joining two lines)
//   - {type: pinned, node: A}                 r_A = X_A, slopes free
//   - {type: prescribed, node: A, velocity: [vx, vy, vz], amplitude: [ax, ay, az],
//      frequency: f}                           r_A = X_A + v t + a sin(2π f t)
#include "scene_build.hpp"
#include "yaml_fields.hpp"

namespace catena::model::detail {

// Not collective. Reads `constraints` after the supports (a constrained position must be
// free) and rejects redundant sets (a node pinned twice, a loop of coincidences, two
// nodes joined to each other and both to ground), whose multipliers would be singular.
void read_constraints(const Field& constraints, SceneBuild& build);

}  // namespace catena::model::detail
