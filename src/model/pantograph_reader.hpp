#pragma once
// `pantographs`: lumped-mass pantographs running along a path of the contact wire, each
// coupled to the wire by penalty contact at its moving position (model::MovingContact).
// A pantograph of n stages becomes n nodes moving vertically (x and y held), point masses,
// vertical springs–dampers between consecutive stages and from the last stage to ground,
// the static uplift (plus the aerodynamic c·v²) as a nodal force on the last stage, and a
// load cancelling the stages' weight (the static uplift is the net force of the
// mechanism, which carries its own weight; EN 50318 models have no gravity on the masses).
#include "scene_build.hpp"
#include "yaml_fields.hpp"

namespace catena::model::detail {

// Not collective. Needs Model::paths (the catenary builder's) and the nodes and elements
// read so far; appends nodes, elements, supports, masses, loads and contacts.
void read_pantographs(const Field& pantographs, SceneBuild& build);

}  // namespace catena::model::detail
