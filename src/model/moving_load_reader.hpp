#pragma once
// The scene's top-level `moving_loads` list (docs/scene.md): constant forces travelling at
// constant speed along a path of named lines, e.g. a pantograph's uplift on the contact
// wire. Each entry becomes a model::MovingLoad whose path is the elements of its lines,
// in order, each line from its `from` to its `to` node. Dynamic analyses only.
#include "catena/model/model.hpp"
#include "scene_build.hpp"
#include "yaml_fields.hpp"

namespace catena::model::detail {

// Not collective. Needs model.analysis, model.dynamic_options.duration (read_dynamics)
// and the generated lines; appends to model.moving_loads.
void read_moving_loads(const Field& moving_loads, SceneBuild& build);

}  // namespace catena::model::detail
