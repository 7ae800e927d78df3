// `catena check --ids`: the ids the catenary builder gave, for attaching loads, masses and
// probes without a first run (docs/catenary.md, "Ids"); the output files store the same
// (docs/output.md, `/catenary`).
#include <cstdio>
#include <string>

#include "catena/model/model_summary.hpp"

namespace catena::model {
namespace {

std::string line(const char* format, auto... values) {
  char text[256];
  std::snprintf(text, sizeof text, format, values...);
  return text;
}

}  // namespace

std::string describe_catenary_ids(const Model& m) {
  if (!m.catenary) return "ids: the scene has no 'catenary'; its nodes and elements are its own\n";
  const CatenaryLayout& c = *m.catenary;
  const auto node_id = [&](int node) {
    return static_cast<long long>(m.nodes[static_cast<std::size_t>(node)].id);
  };
  std::string out = line(
      "catenary ids (docs/catenary.md, \"Ids\"): %zu droppers, %zu supports; node and "
      "element ids as in the scene's loads, masses and probes\n",
      c.droppers.size(), c.support_x.size());
  out +=
      "  droppers (upper wire: the messenger, or stitch wire k; element: the bar, or a "
      "cable dropper's lowest element)\n";
  out += line("  %5s %4s %12s %14s %13s %11s %11s %11s\n", "span", "no.", "x [m]", "design z [m]",
              "contact node", "upper node", "upper wire", "element");
  int number = 0;
  for (std::size_t i = 0; i < c.droppers.size(); ++i) {
    const CatenaryDropper& d = c.droppers[i];
    number = i > 0 && c.droppers[i - 1].span == d.span ? number + 1 : 1;
    const std::string wire = d.stitch < 0 ? "messenger" : "stitch " + std::to_string(d.stitch + 1);
    out += line("  %5d %4d %12.4f %14.6f %13lld %11lld %11s %11lld\n", d.span + 1, number,
                m.nodes[static_cast<std::size_t>(d.contact_node)].position.x(), d.design_z,
                node_id(d.contact_node), node_id(d.upper_node), wire.c_str(),
                static_cast<long long>(m.elements[static_cast<std::size_t>(d.element)].id));
  }
  out += "  supports (contact node: the registration at an intermediate support)\n";
  out +=
      line("  %5s %12s %13s %15s  %s\n", "no.", "x [m]", "contact node", "messenger node", "role");
  for (std::size_t j = 0; j < c.support_x.size(); ++j) {
    const bool end = j == 0 || j + 1 == c.support_x.size();
    out += line("  %5zu %12.4f %13lld %15lld  %s\n", j + 1, c.support_x[j],
                node_id(c.contact_support_nodes[j]), node_id(c.messenger_support_nodes[j]),
                end ? "anchor (both wires pinned)" : "steady arm and messenger support");
  }
  if (c.stitch_wires.empty()) return out;
  out += "  stitch wires (joined at both ends to the messenger nodes of their clamps)\n";
  out +=
      line("  %5s %8s %12s %13s %13s\n", "no.", "support", "x [m]", "clamp node 1", "clamp node 2");
  for (std::size_t k = 0; k < c.stitch_wires.size(); ++k) {
    const CatenaryStitch& s = c.stitch_wires[k];
    out += line("  %5zu %8d %12.4f %13lld %13lld\n", k + 1, s.support + 1,
                c.support_x[static_cast<std::size_t>(s.support)], node_id(s.clamp_nodes[0]),
                node_id(s.clamp_nodes[1]));
  }
  return out;
}

}  // namespace catena::model
