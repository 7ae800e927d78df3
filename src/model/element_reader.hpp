#pragma once
// The scene's explicit `elements`: [{id, section, nodes: [a, b], set, ...}, ...].
// Read in two steps because an element may name a node that a line generates: first the
// entries (before lines), then their node references (after lines).
#include <cstdint>
#include <vector>

#include "element_options.hpp"
#include "scene_build.hpp"
#include "section_reader.hpp"

namespace catena::model::detail {

struct PendingElement {
  ElementDesc desc;              // everything but nodes and the cable prestrain
  std::vector<Field> node_refs;  // the two node ids, resolved by add_explicit_elements
  PrestressSpec prestress;
  Field entry;
};

// Not collective. Reads and validates the entries (ids unique, two nodes, section known,
// options fitting the section kind).
std::vector<PendingElement> read_elements(const Field& elements, const SectionTable& sections);

// Not collective. The largest explicit element id, 0 if there are none: line elements are
// numbered after it.
std::int64_t max_element_id(const std::vector<PendingElement>& elements);

// Not collective. Resolves node ids and prestrain, and puts the explicit elements before
// the lines' in build.model.elements.
void add_explicit_elements(std::vector<PendingElement> elements, SceneBuild& build);

}  // namespace catena::model::detail
