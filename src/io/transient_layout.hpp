#pragma once
// The names in a time-series HDF5 file (dynamic runs), in one place for the readers of the
// file inside the io layer (the XDMF description); docs/output.md documents shapes and
// units. TransientWriter (transient_writer.cpp) writes these names: keep the two in step.
namespace catena::io::transient_layout {

inline constexpr const char* time = "/time";  // (n_samples,)

inline constexpr const char* node_ids = "/mesh/node_ids";              // (n_nodes,) int64
inline constexpr const char* node_positions = "/mesh/node_positions";  // (n_nodes, 3)
inline constexpr const char* element_ids = "/mesh/element_ids";        // (n_elements,) int64
inline constexpr const char* element_nodes = "/mesh/element_nodes";    // (n_elements, 2) int64

// (n_samples, n_nodes, 3)
inline constexpr const char* positions = "/samples/positions";
inline constexpr const char* velocities = "/samples/velocities";
inline constexpr const char* slopes = "/samples/slopes";
// (n_samples, n_elements)
inline constexpr const char* axial_force = "/samples/axial_force";

inline constexpr int nodes_per_element = 2;

}  // namespace catena::io::transient_layout
