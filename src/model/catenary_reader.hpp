#pragma once
// The scene's `catenary`: design data of a simple catenary (one tension section), read and
// range-checked here, built by catenary_builder. Keys, units and ranges: docs/scene.md
// "catenary"; the model it makes: docs/catenary.md.
#include "catena/model/memory_estimate.hpp"
#include "scene_build.hpp"
#include "yaml_fields.hpp"

namespace catena::model::detail {

// Not collective. Reads `catenary` (absent: nothing happens) and adds the catenary to
// build.model. Needs Model::gravity (the catenary's z is up, so gravity must point along
// −z) and comes after the explicit nodes, lines and elements, whose ids it numbers after.
// `scene` is the root: `spans: auto` reads the run's duration and pantographs from it.
// A catenary whose wires and droppers alone exceed `budget` is refused before it is built
// (memory_check.hpp).
void read_catenary(const Field& catenary, const Field& scene, SceneBuild& build,
                   const MemoryBudget& budget);

}  // namespace catena::model::detail
