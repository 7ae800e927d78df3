#include "node_reader.hpp"

namespace catena::model::detail {

void read_nodes(const Field& nodes, SceneBuild& build) {
  static const std::vector<std::string> keys{"id", "position"};
  const std::vector<Field> entries = nodes.items();
  build.model.nodes.reserve(entries.size());
  for (const Field& entry : entries) {
    entry.expect_map("a node {id, position}");
    entry.check_keys(keys);
    Node node;
    node.id = entry.child("id").integer(node_id_range());
    node.position = entry.child("position").vec3(RealRange::any("m"));
    build.add_node(node, build.add_origin(entry));
  }
  build.mark_explicit_nodes_done();
}

}  // namespace catena::model::detail
