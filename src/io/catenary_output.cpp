#include "catenary_output.hpp"

#include <cstdint>
#include <vector>

#include "catena/core/mpi_comm.hpp"
#include "catenary_output_layout.hpp"

namespace catena::io {
namespace {

namespace layout = catenary_layout;

// Collective. A 1-D dataset of `values` (rank 0's; the other ranks pass theirs empty).
template <class Value>
void write_rows(const ParallelHdf5File& file, const char* name, const std::vector<Value>& values,
                std::int64_t n_rows, const char* unit = nullptr) {
  const RowBlock block{0, static_cast<std::int64_t>(values.size())};
  write_block_dataset<Value>(file, {name, n_rows, 1, unit}, block, values);
}

}  // namespace

void write_catenary_layout(const ParallelHdf5File& file, const model::Model& model) {
  if (!model.catenary) return;
  const model::CatenaryLayout& c = *model.catenary;
  const bool root = mpi_rank(file.comm()) == 0;
  const auto node_id = [&](int node) { return model.nodes[static_cast<std::size_t>(node)].id; };

  std::vector<std::int32_t> span, number, upper_wire;
  std::vector<std::int64_t> contact_node, upper_node, element;
  std::vector<double> x, design_height, unstretched_length;
  if (root) {
    for (const model::CatenaryDropper& d : c.droppers) {
      number.push_back(!span.empty() && span.back() == d.span + 1 ? number.back() + 1 : 1);
      span.push_back(d.span + 1);
      x.push_back(model.nodes[static_cast<std::size_t>(d.contact_node)].position.x());
      contact_node.push_back(node_id(d.contact_node));
      upper_node.push_back(node_id(d.upper_node));
      upper_wire.push_back(d.stitch + 1);
      element.push_back(model.elements[static_cast<std::size_t>(d.element)].id);
      design_height.push_back(d.design_z);
      unstretched_length.push_back(d.unstretched_length);
    }
  }
  const auto n = static_cast<std::int64_t>(c.droppers.size());
  create_group(file, layout::group);
  create_group(file, layout::droppers_group);
  write_rows(file, layout::dropper_span, span, n);
  write_rows(file, layout::dropper_number, number, n);
  write_rows(file, layout::dropper_x, x, n, "m");
  write_rows(file, layout::dropper_contact_node_id, contact_node, n);
  write_rows(file, layout::dropper_upper_node_id, upper_node, n);
  write_rows(file, layout::dropper_upper_wire, upper_wire, n);
  write_rows(file, layout::dropper_element_id, element, n);
  write_rows(file, layout::dropper_design_height, design_height, n, "m");
  write_rows(file, layout::dropper_unstretched_length, unstretched_length, n, "m");

  std::vector<double> support_x;
  std::vector<std::int64_t> contact_support, messenger_support;
  if (root) {
    support_x = c.support_x;
    for (const int node : c.contact_support_nodes) contact_support.push_back(node_id(node));
    for (const int node : c.messenger_support_nodes) messenger_support.push_back(node_id(node));
  }
  const auto n_supports = static_cast<std::int64_t>(c.support_x.size());
  create_group(file, layout::supports_group);
  write_rows(file, layout::support_x, support_x, n_supports, "m");
  write_rows(file, layout::support_contact_node_id, contact_support, n_supports);
  write_rows(file, layout::support_messenger_node_id, messenger_support, n_supports);
}

}  // namespace catena::io
