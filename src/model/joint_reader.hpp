#pragma once
// `joints`: joints between rigid bodies, a body and a node, or a body and the ground
// (model::Joint), each appended to the model's constraints as one of type `joint`.
#include "scene_build.hpp"
#include "yaml_fields.hpp"

namespace catena::model::detail {

// Not collective. After the bodies and every other constraint are read (a joint's
// constraint comes after them, so that the scene's constraints keep their numbers).
void read_joints(const Field& joints, SceneBuild& build);

// Not collective. Appends `joint` (its sides, point, axis and coordinate set) and its
// constraint of type `joint`; a ground side has body_b = node_b = −1.
void append_joint(Model& model, const Joint& joint);

}  // namespace catena::model::detail
