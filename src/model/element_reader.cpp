#include "element_reader.hpp"

#include <algorithm>
#include <map>
#include <unordered_map>

namespace catena::model::detail {
namespace {

const std::vector<std::string>& element_keys() {
  static const std::vector<std::string> keys = [] {
    std::vector<std::string> k{"id", "section", "nodes", "set"};
    k.insert(k.end(), element_option_keys().begin(), element_option_keys().end());
    return k;
  }();
  return keys;
}

std::vector<Field> read_node_refs(const Field& nodes) {
  const std::string expected = "a list of 2 node ids [a, b]";
  if (!nodes.present()) nodes.fail("missing required key; expected " + expected);
  if (!nodes.is_list() || nodes.node().size() != 2) {
    const std::string count =
        nodes.is_list() ? " (" + std::to_string(nodes.node().size()) + " items)" : "";
    nodes.fail("expected " + expected + " (every element kind joins exactly 2 nodes), got " +
               nodes.value_text() + count);
  }
  return nodes.items();
}

}  // namespace

std::vector<PendingElement> read_elements(const Field& elements, const SectionTable& sections) {
  std::vector<PendingElement> out;
  std::unordered_map<std::int64_t, std::size_t> first_with_id;
  std::unordered_map<const Section*, SharedProps> shared;  // one block per section
  for (const Field& entry : elements.items()) {
    entry.expect_map("an element {id, section, nodes, ...}");
    entry.check_keys(element_keys());
    const Field id = entry.child("id");
    PendingElement element{ElementDesc{}, {}, PrestressSpec{}, entry};
    element.desc.id = id.integer(IntRange::any("an element id"));
    const auto [first, inserted] = first_with_id.emplace(element.desc.id, out.size());
    if (!inserted) {
      const Field& other = out[first->second].entry;
      id.fail("duplicate element id " + std::to_string(element.desc.id) + " (first used at " +
              other.path() + ", line " + std::to_string(other.location().line) +
              "); element ids must be unique");
    }
    const Section& section = find_section(sections, entry.child("section"));
    element.node_refs = read_node_refs(entry.child("nodes"));
    element.desc.props = shared.try_emplace(&section, section.props).first->second;
    element.desc.set = entry.child("set").text_or("");
    element.prestress = read_prestress(entry, section);
    element.desc.distributed_load = read_distributed_load(entry, section);
    out.push_back(std::move(element));
  }
  return out;
}

std::int64_t max_element_id(const std::vector<PendingElement>& elements) {
  std::int64_t highest = 0;
  for (const PendingElement& e : elements) highest = std::max(highest, e.desc.id);
  return highest;
}

void add_explicit_elements(std::vector<PendingElement> elements, SceneBuild& build) {
  std::vector<ElementDesc> descs;
  std::vector<int> origins;
  descs.reserve(elements.size());
  origins.reserve(elements.size());
  // The cables of one section given the same prestrain share one block: keyed by the
  // section's block and the prestrain; the section's handle is kept so that its address
  // stays its own.
  std::map<std::pair<const ElementProps*, double>, std::pair<SharedProps, SharedProps>> prestrained;
  for (PendingElement& element : elements) {
    const int a = build.resolve_node(element.node_refs[0]);
    const int b = build.resolve_node(element.node_refs[1]);
    if (a == b)
      element.entry.child("nodes").fail("both nodes are node " +
                                        std::to_string(build.model.nodes[a].id) +
                                        "; an element joins two different nodes");
    element.desc.nodes = {a, b};
    if (const auto* cable = std::get_if<CableProps>(&*element.desc.props)) {
      const double length = (build.model.nodes[b].position - build.model.nodes[a].position).norm();
      const double prestrain = resolve_prestrain(element.prestress, cable->EA, length);
      auto [it, added] = prestrained.try_emplace({&*element.desc.props, prestrain},
                                                 element.desc.props, element.desc.props);
      if (added) std::get<CableProps>(it->second.second.edit()).prestrain = prestrain;
      element.desc.props = it->second.second;
    }
    descs.push_back(std::move(element.desc));
    origins.push_back(build.add_origin(element.entry));
  }
  if (!descs.empty()) build.prepend_elements(std::move(descs), origins);
}

}  // namespace catena::model::detail
