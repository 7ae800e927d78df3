#pragma once
// The scene's `lines`: straight runs of equal elements between two explicit nodes.
//
// Numbering (docs/scene.md "Generated ids"): the interior nodes of all lines get ids
// max(0, largest explicit node id) + 1, + 2, ... in the order lines appear, and are
// appended to Model::nodes after the explicit nodes; line elements get ids after the
// largest explicit element id likewise. A line's elements run from `from` to `to`, each
// from its first node to its second, and belong to the set named like the line.
#include <cstdint>

#include "scene_build.hpp"
#include "section_reader.hpp"

namespace catena::model::detail {

// Not collective. Appends the lines' interior nodes and their elements to `build`; line
// element ids start after largest_element_id (max(0, largest explicit element id)).
void generate_lines(const Field& lines, const SectionTable& sections, SceneBuild& build,
                    std::int64_t largest_element_id);

}  // namespace catena::model::detail
