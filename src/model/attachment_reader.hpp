#pragma once
// What the scene attaches to single nodes: `supports` (fixed DOFs), `elastic_supports`
// (springs and dashpots to ground), `loads` (nodal forces) and `masses` (point masses).
#include <vector>

#include "catena/model/unknown_kinds.hpp"
#include "scene_build.hpp"
#include "yaml_fields.hpp"

namespace catena::model::detail {

// Not collective. Reads `supports`; `node_kinds` (per node, model/node_kinds.hpp) decides
// which components exist at each node. At most one support per node.
void read_supports(const Field& supports, const std::vector<UnknownKind>& node_kinds,
                   SceneBuild& build);

// Not collective. Read `elastic_supports`, `loads` and `masses` (several per node add up).
void read_elastic_supports(const Field& elastic_supports, SceneBuild& build);
// `absorbing_ends`: after the supports, constraints and joints (which it checks against).
void read_absorbing_ends(const Field& absorbing_ends, SceneBuild& build);
void read_loads(const Field& loads, SceneBuild& build);
void read_masses(const Field& masses, SceneBuild& build);

}  // namespace catena::model::detail
