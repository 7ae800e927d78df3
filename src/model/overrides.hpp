#pragma once
// `--set dotted.path=value` overrides, applied to the YAML tree before validation so that
// an overridden value is checked exactly like one written in the file.
//
// Path syntax: keys separated by '.', list items by [index]: "output.file",
// "lines[0].elements", "sections.cw.EA", "analysis.newton.rtol". Missing map keys (and
// missing maps on the way) are created; list items must already exist (no appending: the
// index would depend on the file). The value is YAML: "7", "run.h5", "[0, 0, -5]".
#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "yaml_fields.hpp"

namespace catena::model::detail {

// Not collective. Applies `overrides` in order to `root` (a map). Throws InputError for a
// malformed override (no '=', empty path or key, bad index, a path through a scalar or a
// list item that does not exist) naming `file_label` and the override.
std::vector<AppliedOverride> apply_overrides(YAML::Node& root,
                                             const std::vector<std::string>& overrides,
                                             const std::string& file_label);

}  // namespace catena::model::detail
