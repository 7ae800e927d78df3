#pragma once
// Reference nodal frames (Node::tangent, section_y, section_z) and the geometric checks
// they rest on.
//
// ANCF nodes carry slope vectors r_x (cables, beams) and r_y, r_z (beams) that are
// continuous across the node, so every cable and beam element at a node must run along
// the same line in the same direction (from its first to its second node), within 1e-9
// in the unit direction. A corner needs two nodes joined by a short stiff element.
#include "scene_build.hpp"

namespace catena::model::detail {

// Not collective. Errors if a cable, beam or bar element has zero length (its two nodes
// coincide within SceneBuild::zero_length_tolerance). Springs may have zero length: their
// force depends only on the nodes' displacements.
void check_element_lengths(const SceneBuild& build);

// Not collective. Sets tangent = unit element direction at nodes of cables and beams, and
// at beam nodes section_y = the section's y_axis made orthogonal to the tangent and
// section_z = tangent × section_y. Errors on kinked or reversed slopes at a node, on a
// y_axis (nearly) parallel to a beam's axis (|sin| < 1e-6) and on beams that give a node
// different section axes. Requires check_element_lengths to have passed.
void assign_nodal_frames(SceneBuild& build);

}  // namespace catena::model::detail
