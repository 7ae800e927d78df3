#include "static_result_checks.hpp"

#include <algorithm>
#include <span>
#include <string>

#include "catena/core/error.hpp"
#include "row_redistribution.hpp"
#include "static_result_layout.hpp"

namespace catena::io {
namespace {

void check_value_count(std::size_t n_values, std::size_t n_rows, std::size_t per_row,
                       const char* values_name, const char* rows_name) {
  if (n_values != n_rows * per_row)
    throw Error(std::string("StaticResult::") + values_name + " has " + std::to_string(n_values) +
                " values; expected " + std::to_string(per_row) + " per entry of " + rows_name +
                " (" + std::to_string(n_rows * per_row) + ")");
}

}  // namespace

void check_result_matches_model(const model::Model& model, const StaticResult& result) {
  const auto n_nodes = static_cast<std::int64_t>(model.nodes.size());
  const auto n_elements = static_cast<std::int64_t>(model.elements.size());
  check_rows_strictly_ascending(result.owned_nodes, n_nodes, "StaticResult::owned_nodes");
  check_rows_strictly_ascending(result.owned_elements, n_elements, "StaticResult::owned_elements");
  check_rows_strictly_ascending(result.support_nodes, n_nodes, "StaticResult::support_nodes");

  const std::size_t n_owned_nodes = result.owned_nodes.size();
  const std::size_t n_owned_elements = result.owned_elements.size();
  const std::size_t n_supports = result.support_nodes.size();
  check_value_count(result.positions.size(), n_owned_nodes, 3, "positions", "owned_nodes");
  check_value_count(result.slopes.size(), n_owned_nodes, 3, "slopes", "owned_nodes");
  check_value_count(result.axial_force.size(), n_owned_elements, 1, "axial_force",
                    "owned_elements");
  check_value_count(result.axial_strain.size(), n_owned_elements, 1, "axial_strain",
                    "owned_elements");
  check_value_count(result.shear_force.size(), n_owned_elements, 3, "shear_force",
                    "owned_elements");
  check_value_count(result.bending_moment.size(), n_owned_elements, 3, "bending_moment",
                    "owned_elements");
  check_value_count(result.torsion.size(), n_owned_elements, 1, "torsion", "owned_elements");
  check_value_count(result.reaction_force.size(), n_supports, 3, "reaction_force", "support_nodes");
  check_value_count(result.reaction_moment.size(), n_supports, 3, "reaction_moment",
                    "support_nodes");

  // A support row is written by the rank that reports it; requiring it to be an owned
  // node makes support rows disjoint across ranks, as owned nodes are.
  for (const int node : result.support_nodes)
    if (!std::binary_search(result.owned_nodes.begin(), result.owned_nodes.end(), node))
      throw Error("StaticResult::support_nodes lists node " + std::to_string(node) +
                  ", which is not among this rank's owned_nodes");

  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    const model::ElementDesc& element = model.elements[e];
    if (element.nodes.size() != static_cast<std::size_t>(static_layout::nodes_per_element))
      throw Error("element " + std::to_string(element.id) + " has " +
                  std::to_string(element.nodes.size()) + " nodes; the output format (" +
                  static_layout::format + ") stores 2-node elements only");
    for (const int node : element.nodes)
      if (node < 0 || node >= n_nodes)
        throw Error("element " + std::to_string(element.id) + " refers to node index " +
                    std::to_string(node) + ", outside [0, " + std::to_string(n_nodes) + ")");
  }
}

void check_output_paths(const std::filesystem::path& hdf5_path,
                        const std::filesystem::path& xdmf_path) {
  if (hdf5_path.filename().empty())
    throw Error("the output path '" + hdf5_path.string() + "' does not name a file");
  if (hdf5_path.extension() == ".xmf")
    throw Error("the output path '" + hdf5_path.string() +
                "' ends in .xmf, the name reserved for its XDMF companion; use .h5");
  const std::filesystem::path directory =
      hdf5_path.has_parent_path() ? hdf5_path.parent_path() : std::filesystem::path(".");
  std::error_code error;
  if (!std::filesystem::is_directory(directory, error))
    throw Error("the directory '" + directory.string() + "' does not exist");
  for (const std::filesystem::path& target : {hdf5_path, xdmf_path})
    if (std::filesystem::is_directory(target, error))
      throw Error("'" + target.string() + "' is a directory");
}

}  // namespace catena::io
