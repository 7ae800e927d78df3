#pragma once
// How the state of a windowed catenary (model::CatenaryWindow) moves when the window moves
// a period ahead along its line: each node takes the state of the node one period ahead of
// it (its reference position plus the window's shift), the nodes of the last period take
// the static state (the line ahead is at rest), and the pantographs' nodes keep theirs.
// The map is found on the reference geometry, element by element, so that nodes at one
// point (a staggered wire's two nodes at a support, a cable dropper's hinge) are told
// apart by the elements they belong to.
#include <vector>

#include "catena/model/model.hpp"

namespace catena::model {

inline constexpr int kWindowEnters = -1;  // no image inside the window

// Which image of a node: the node one period ahead of it (the state it takes when the
// window moves) or one period behind it.
enum class WindowImage { ahead, behind };

// Not collective. Per node of `model` (which has a window): its image, kWindowEnters where
// the image lies outside the window (or on its end), or the node itself (a pantograph's).
// Throws Error naming a node if the built window does not repeat (a node with an image
// inside the window but no node there of the same elements).
std::vector<int> window_state_sources(const Model& model, WindowImage image);

}  // namespace catena::model
