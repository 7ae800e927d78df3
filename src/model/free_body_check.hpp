#pragma once
// Rejects scenes with a part that nothing holds: a connected component of the graph whose
// vertices are nodes and whose edges are elements, containing no node with a support or
// an elastic support. Its stiffness matrix would be singular (rigid-body motion), which
// the solver would only report as a failed factorisation.
#include "scene_build.hpp"

namespace catena::model::detail {

// Not collective. Errors naming some of the unsupported part's node ids.
void check_no_free_body(const SceneBuild& build);

}  // namespace catena::model::detail
