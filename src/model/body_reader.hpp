#pragma once
// `bodies`: rigid bodies in natural coordinates (model::RigidBody), each on a node of its
// own, and the two constraints per body that keep its axes orthonormal.
#include "scene_build.hpp"
#include "yaml_fields.hpp"

namespace catena::model::detail {

// Not collective. Reads `bodies` into build.model.rigid_bodies and sets each body node's
// reference frame (Node::tangent, section_y, section_z) to the body's initial axes. After
// the nodal frames are assigned (a node a cable or beam runs through cannot carry a body),
// before supports (which need the nodes' kinds).
void read_bodies(const Field& bodies, SceneBuild& build);

// Not collective. Appends each body's frame_lengths and frame_angles constraints (after the
// scene's own constraints, whose numbering in messages stays the scene's), and refuses
// supports that fix a body's axes (with the frame constraints, singular). After the
// supports and constraints are read.
void add_body_frame_constraints(const Field& bodies, SceneBuild& build);

// Not collective. Appends `body`'s two frame constraints and records the first's index.
void append_frame_constraints(Model& model, RigidBody& body);

}  // namespace catena::model::detail
