#pragma once
// The XDMF (eXtensible Data Model and Format, version 3) description of a static-result
// HDF5 file, which lets ParaView and VisIt open it: a polyline mesh on the deformed
// positions with node and cell fields. The XDMF only points into the HDF5 file, by its
// base name, so the pair can be moved together.
#include <cstdint>
#include <filesystem>
#include <string>

namespace catena::io {

// What the XDMF must know about the HDF5 file it describes.
struct XdmfStaticGrid {
  std::string hdf5_file_name;  // base name, resolved relative to the .xmf's directory
  std::int64_t n_nodes = 0;
  std::int64_t n_elements = 0;
};

// Not collective. `hdf5_path` with its extension replaced by ".xmf" (appended if none).
std::filesystem::path xdmf_path_for(const std::filesystem::path& hdf5_path);

// Not collective. The XDMF document (UTF-8 XML text).
std::string static_result_xdmf(const XdmfStaticGrid& grid);

// Not collective. `text` with the five XML special characters replaced by entities, for
// attribute values and element content.
std::string xml_escaped(const std::string& text);

}  // namespace catena::io
