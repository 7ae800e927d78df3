#pragma once
// The reference mesh as both result files store it (the static result,
// static_result_layout.hpp, and the time series, transient_layout.hpp): the same group and
// datasets, so a reader of one reads the mesh of the other. docs/output.md documents them.
namespace catena::io::mesh_layout {

inline constexpr const char* group = "/mesh";
inline constexpr const char* node_ids = "/mesh/node_ids";              // (n_nodes,) int64
inline constexpr const char* node_positions = "/mesh/node_positions";  // (n_nodes, 3) float64, m
inline constexpr const char* element_ids = "/mesh/element_ids";        // (n_elements,) int64
// (n_elements, nodes_per_element) int64: node indices (0-based rows), A then B.
inline constexpr const char* element_nodes = "/mesh/element_nodes";

// Every element is a 2-node element so far; the XDMF topologies rely on it.
inline constexpr int nodes_per_element = 2;

}  // namespace catena::io::mesh_layout
