#pragma once
// The names in a static-result HDF5 file, in one place: the HDF5 writer and the XDMF
// writer both use them, and docs/output.md documents them (shapes, types, units).
// Changing a name or a meaning means a new `format` string.
#include <cstdint>

#include "mesh_layout.hpp"

namespace catena::io::static_layout {

inline constexpr const char* format = "catena-static-1";
inline constexpr const char* units = "SI";

// The reference mesh (mesh_layout.hpp), and what only the static file adds to it.
inline constexpr const char* mesh_group = mesh_layout::group;
inline constexpr const char* node_ids = mesh_layout::node_ids;
inline constexpr const char* node_positions = mesh_layout::node_positions;
inline constexpr const char* element_ids = mesh_layout::element_ids;
inline constexpr const char* element_nodes = mesh_layout::element_nodes;
inline constexpr const char* element_kind = mesh_layout::element_kind;
inline constexpr const char* element_set = mesh_layout::element_set;

inline constexpr const char* static_group = "/static";
inline constexpr const char* positions = "/static/positions";
inline constexpr const char* slopes = "/static/slopes";
inline constexpr const char* displacements = "/static/displacements";
inline constexpr const char* axial_force = "/static/axial_force";
inline constexpr const char* axial_strain = "/static/axial_strain";
inline constexpr const char* shear_force = "/static/shear_force";
inline constexpr const char* bending_moment = "/static/bending_moment";
inline constexpr const char* torsion = "/static/torsion";
inline constexpr const char* support_nodes = "/static/support_nodes";
inline constexpr const char* reaction_force = "/static/reaction_force";
inline constexpr const char* reaction_moment = "/static/reaction_moment";

inline constexpr int nodes_per_element = mesh_layout::nodes_per_element;

// Values of /mesh/element_kind and /mesh/element_set: mesh_layout.hpp.
inline constexpr std::int32_t no_set = mesh_layout::no_set;

}  // namespace catena::io::static_layout
