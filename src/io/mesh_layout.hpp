#pragma once
// The reference mesh as both result files store it (the static result,
// static_result_layout.hpp, and the time series, transient_layout.hpp): the same group and
// datasets, so a reader of one reads the mesh of the other. docs/output.md documents them.
#include <cstdint>

namespace catena::io::mesh_layout {

inline constexpr const char* group = "/mesh";
inline constexpr const char* node_ids = "/mesh/node_ids";              // (n_nodes,) int64
inline constexpr const char* node_positions = "/mesh/node_positions";  // (n_nodes, 3) float64, m
inline constexpr const char* element_ids = "/mesh/element_ids";        // (n_elements,) int64
// (n_elements, nodes_per_element) int64: node indices (0-based rows), A then B.
inline constexpr const char* element_nodes = "/mesh/element_nodes";

// (n_elements,) int8: model::element_kind_code; attribute "kinds": the names in code order.
inline constexpr const char* element_kind = "/mesh/element_kind";
// (n_elements,) int32: index into the attribute "set_names" (sorted), no_set for none.
inline constexpr const char* element_set = "/mesh/element_set";
inline constexpr std::int32_t no_set = -1;

// Every element is a 2-node element so far; the XDMF topologies rely on it.
inline constexpr int nodes_per_element = 2;

}  // namespace catena::io::mesh_layout
