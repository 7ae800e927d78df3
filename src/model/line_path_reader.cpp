#include "line_path_reader.hpp"

#include <variant>

#include "catena/model/element_kinds.hpp"
#include "did_you_mean.hpp"

namespace catena::model::detail {
namespace {

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& n : names) text += (text.empty() ? "" : ", ") + n;
  return text.empty() ? "(none)" : text;
}

// One line of a path: its name, where it was named, and its elements.
struct PathLine {
  std::string name;
  Field where;
  const std::vector<int>* elements;
};

// The line named at `reference`; errors if there is none or it is not a cable/beam line.
PathLine resolve_line(const Field& reference, const LineTable& lines, const Model& model,
                      const char* what) {
  const std::string name = reference.text();
  const auto it = lines.elements.find(name);
  if (it == lines.elements.end())
    reference.fail("no line named '" + name + "';" + did_you_mean(name, lines.names) +
                   " expected the name of a line under 'lines'; lines: " + joined(lines.names));
  // Every element of a line has the line's section, so the first one tells the kind.
  const ElementProps& props = *model.elements[it->second.front()].props;
  if (!std::holds_alternative<CableProps>(props) && !std::holds_alternative<BeamProps>(props))
    reference.fail("line '" + name + "' is made of " + std::string(element_kind_name(props)) +
                   " elements; " + std::string(what) +
                   " run on cable or beam lines (their shape functions place the point "
                   "between the nodes)");
  return {name, reference, &it->second};
}

}  // namespace

LineTable named_lines(const SceneBuild& build) {
  LineTable table;
  const std::vector<ElementDesc>& elements = build.model.elements;
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const std::string& name = elements[e].set;
    const int index = static_cast<int>(e);
    if (name.empty() || !build.element_origin(index).path().starts_with("lines[")) continue;
    const auto [it, inserted] = table.elements.try_emplace(name);
    if (inserted) table.names.push_back(name);
    it->second.push_back(index);
  }
  return table;
}

// The element path of `line`: one line name, or a list of names in path order whose ends
// connect (the last node of each is the first node of the next).
std::vector<int> read_path(const Field& line, const LineTable& lines, const Model& model,
                           const char* what) {
  const std::string expected = "a line name or a list of line names in path order";
  if (!line.present()) line.fail("missing required key; expected " + expected);
  if (line.node().IsNull()) line.fail("no value given; expected " + expected);
  if (line.is_map()) line.fail("expected " + expected + ", got " + line.value_text());
  std::vector<Field> references;
  if (line.is_list()) {
    references = line.items();
    if (references.empty()) line.fail("the path is empty; expected " + expected);
  } else {
    references.push_back(line);
  }

  std::vector<PathLine> path;
  std::vector<int> elements;
  for (const Field& reference : references) {
    const PathLine next = resolve_line(reference, lines, model, what);
    for (const PathLine& earlier : path)
      if (earlier.name == next.name)
        reference.fail("line '" + next.name + "' appears twice in the path (first at " +
                       earlier.where.path() + "); a path runs along each line once");
    if (!path.empty()) {
      const PathLine& previous = path.back();
      const int end = model.elements[previous.elements->back()].nodes.back();
      const int start = model.elements[next.elements->front()].nodes.front();
      if (end != start)
        reference.fail("lines '" + previous.name + "' and '" + next.name + "' do not connect: '" +
                       previous.name + "' ends at node " + std::to_string(model.nodes[end].id) +
                       " but '" + next.name + "' starts at node " +
                       std::to_string(model.nodes[start].id) +
                       "; expected consecutive lines of the path to share a node (the 'to' of "
                       "one is the 'from' of the next)");
    }
    path.push_back(next);
    elements.insert(elements.end(), next.elements->begin(), next.elements->end());
  }
  return elements;
}

namespace {

int find_path(const Field& where, const Model& m) {
  const std::string name = where.text();
  std::vector<std::string> names;
  for (size_t i = 0; i < m.paths.size(); ++i) {
    if (m.paths[i].name == name) return static_cast<int>(i);
    names.push_back(m.paths[i].name);
  }
  where.fail("no path named '" + name + "';" + did_you_mean(name, names) +
             (names.empty() ? " this scene has no paths (a `catenary` makes 'contact_wire')"
                            : " known paths: " + joined(names)));
}

}  // namespace

int read_path_or_line(const Field& entry, SceneBuild& build, const std::string& own_name,
                      const char* what) {
  const Field path = entry.child("path"), line = entry.child("line");
  if (path.present() == line.present())
    entry.fail(
        "give exactly one of path (a path the catenary builder made, e.g. "
        "contact_wire) and line (a line name or a list of them in travel order)");
  Model& m = build.model;
  if (path.present()) return find_path(path, m);
  ElementPath own;
  own.name = own_name;
  own.elements = read_path(line, named_lines(build), m, what);
  m.paths.push_back(own);
  return static_cast<int>(m.paths.size()) - 1;
}

}  // namespace catena::model::detail
