#pragma once
// `surfaces`: rigid planes that listed nodes touch (model::Surface; a penalty contact with
// damping and Coulomb friction on each node).
#include "scene_build.hpp"
#include "yaml_fields.hpp"

namespace catena::model::detail {

// Not collective. Reads `surfaces` into build.model.surfaces: each a plane (point, normal),
// its contact law and its nodes (`nodes`, a list of ids, and/or `line`, every node of a
// line's elements), which must start on the plane's free side. After the nodes, lines and
// bodies.
void read_surfaces(const Field& surfaces, SceneBuild& build);

}  // namespace catena::model::detail
