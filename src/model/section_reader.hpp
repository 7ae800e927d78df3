#pragma once
// The scene's `sections`: named property sets (one per kind of element: cable, beam, bar,
// spring) that lines and elements refer to by name. Keys, units and ranges: docs/scene.md
// "sections"; each kind declares them with its properties (catena/model/element_props.hpp).
#include <map>
#include <string>

#include "catena/model/model.hpp"
#include "yaml_fields.hpp"

namespace catena::model::detail {

struct Section {
  std::string name;
  ElementProps props;  // its kind (std::holds_alternative, element_kind_name) and values,
                       // copied into every element of this section
};

using SectionTable = std::map<std::string, Section, std::less<>>;

// Not collective. Reads and validates the `sections` map (absent: no sections).
SectionTable read_sections(const Field& sections);

// Not collective. The section a line's or element's `section:` key names; errors with the
// defined names (and the closest one) if there is none.
const Section& find_section(const SectionTable& sections, const Field& reference);

// Not collective. A spring's (or elastic support's) `stiffness`: a scalar s ([s, s, s]) or
// [kx, ky, kz], each >= 0 N/m and not all zero (no stiffness at all only adds a singular
// block). Required.
Vec3 read_spring_stiffness(const Field& stiffness);
// Not collective. `damping`: a scalar or [cx, cy, cz], each >= 0 N·s/m; absent = zero.
Vec3 read_spring_damping(const Field& damping);

}  // namespace catena::model::detail
