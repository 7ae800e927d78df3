#pragma once
// The scene's explicit `nodes`: [{id, position}, ...].
#include "scene_build.hpp"
#include "yaml_fields.hpp"

namespace catena::model::detail {

// Not collective. Appends the explicit nodes to build.model.nodes (ids unique, positions
// finite) and marks them as the explicit ones.
void read_nodes(const Field& nodes, SceneBuild& build);

}  // namespace catena::model::detail
