#pragma once
// Paths along named lines (`line: name` or `line: [name, ...]` in path order), shared by
// the readers of moving loads and pantographs.
#include <map>
#include <string>
#include <vector>

#include "scene_build.hpp"
#include "yaml_fields.hpp"

namespace catena::model::detail {

// The scene's named lines: the element indices of each, from its `from` to its `to` node
// (the order line_generator appends them in). Only generated elements count: an explicit
// element whose `set` happens to equal a line's name is not part of that line.
struct LineTable {
  std::map<std::string, std::vector<int>> elements;
  std::vector<std::string> names;  // in document order, for messages
};

LineTable named_lines(const SceneBuild& build);

// The element path named at `line`: one line name, or a list of names in path order whose
// ends connect. `what` names the users in messages ("moving loads", "pantographs").
std::vector<int> read_path(const Field& line, const LineTable& lines, const Model& model,
                           const char* what);

// The path an entry runs along: `path` (a path the catenary builder made, by name) or
// `line` (read_path; appended to build.model.paths as `own_name`), exactly one of them.
// Returns its index in build.model.paths.
int read_path_or_line(const Field& entry, SceneBuild& build, const std::string& own_name,
                      const char* what);

}  // namespace catena::model::detail
