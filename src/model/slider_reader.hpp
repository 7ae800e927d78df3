#pragma once
// `sliders`: nodes that run along a path of cable or beam elements (model::Slider), each
// held to its path by one constraint (type slider).
#include "scene_build.hpp"
#include "yaml_fields.hpp"

namespace catena::model::detail {

// Not collective. Reads `sliders` into build.model.sliders: each on a node of its own that
// lies on its path's reference curve (its arc length there becomes the slider's start).
// After the nodal frames and the bodies, before supports (which need the nodes' kinds).
void read_sliders(const Field& sliders, SceneBuild& build);

// Not collective. Refuses a slider whose node carries nothing (no mass, element, elastic
// support or joint): its acceleration would be undetermined. After masses and joints.
void check_sliders_carried(const Field& sliders, const SceneBuild& build);

// Not collective. Appends each slider's constraint (after the scene's own constraints and
// the bodies' frames, so that the scene's numbering in messages stays its own).
void add_slider_constraints(SceneBuild& build);

}  // namespace catena::model::detail
