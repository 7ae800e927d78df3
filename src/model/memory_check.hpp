#pragma once
// The scene reader's memory checks (catena/model/memory_estimate.hpp): a scene whose
// estimated run does not fit the budget is refused with the estimate and the limit, naming
// the key that makes it large. Lines are counted before they are generated, so that
// `catena check` of a scene of 10⁷ elements answers at once instead of building them.
#include "catena/model/memory_estimate.hpp"
#include "catenary_builder.hpp"
#include "scene_build.hpp"
#include "section_reader.hpp"

namespace catena::model::detail {

// Not collective. Before generate_lines: refuses `lines` if even the lines alone (a lower
// bound: the least DOFs per node, the integrator's least linear algebra) exceed the budget.
// Malformed lines are skipped here; generate_lines reports them.
void check_lines_fit(const Field& lines, const SectionTable& sections, const SceneBuild& build,
                     const MemoryBudget& budget);

// Not collective. Before build_catenary: refuses the catenary `d` (after its window cut, if
// any) if even its wires and droppers alone (a lower bound, as for lines) exceed the budget,
// naming `element_length`: `catena check` of a 10 000-span line of cable droppers answers
// at once instead of building 9.5 million elements (25 s and 4.8 GB) to refuse them.
void check_catenary_fits(const Field& element_length, const CatenaryDesign& d,
                         const SceneBuild& build, const MemoryBudget& budget);

// Not collective. Once the model is complete: refuses it if its estimate exceeds the
// budget, naming the scene entry with the most elements.
void check_model_fits(const Field& scene, const SceneBuild& build, const MemoryBudget& budget);

}  // namespace catena::model::detail
