#pragma once
// `catenary.window: {spans, behind}` (docs/scene.md): model a few spans of a long line
// around the pantographs instead of the whole line. The scene still describes the line
// (its spans, evaluation section and the pantographs' starts are the line's); the reader
// builds `spans` of it, placed where the first pantograph on the contact wire starts, and
// the run moves the window along (model/catenary_window.hpp).
#include <optional>
#include <utility>

#include "catena/model/catenary_layout.hpp"
#include "catenary_builder.hpp"
#include "yaml_fields.hpp"

namespace catena::model::detail {

// Not collective. None without the key. Checks that the line repeats (equal spans, the
// same droppers in every span), that the window is shorter than the line and holds a
// span ahead of the pantograph, and fails at `window` (or inside it) otherwise. Places
// the window from the scene's first pantograph on the contact wire (read ahead of the
// pantograph reader, which checks it again in full).
std::optional<CatenaryWindow> read_catenary_window(const Field& catenary, const Field& scene,
                                                   const CatenaryDesign& design);

// Not collective. Makes `design` the window's: its spans and per-span data cut to the
// window's, its first support at the window's place on the line, no evaluation section
// (the line's is set after building: set_window_evaluation) and absorbing ends.
void cut_design_to_window(const CatenaryWindow& window, CatenaryDesign& design);

// Not collective. After building the window: records it in the model's catenary layout
// (with the path length per span) and sets the line's evaluation section, in m along the
// line's contact wire.
void place_window(CatenaryWindow window, const std::optional<std::pair<int, int>>& evaluation_spans,
                  Model& model);

// Not collective. In a scene with a window, moves pantograph `c` (read from `entry`, its
// start on the line) to the window's path: c.start becomes its start along the window.
// Fails unless it runs on the contact wire at the first pantograph's speed and stays a
// span from either end of the window while the window follows the first. Nothing without
// a window.
void place_pantograph_in_window(const Field& entry, const Model& model, MovingContact& c);

// Not collective. After the whole scene is read: a window holds the catenary and the
// pantographs only (every other node stays where it is while the line's state moves), with a
// one-step integrator (HHT or implicit Runge–Kutta: a multistep history cannot move with
// the window) and a structure that is nonlinear or linear (modal coordinates do not move
// along a line). Fails at the key that stands in the way. Nothing without a window.
void check_window_scene(const Field& scene, const Model& model);

}  // namespace catena::model::detail
