// write_modes: the modes as one HDF5 file written by all ranks through MPI-IO (the node
// rows moved to balanced blocks first, row_redistribution.hpp) and an XDMF file, both
// renamed into place at the end (atomic_file.hpp). Layout: docs/output.md, "Modes".

#include <filesystem>
#include <optional>
#include <sstream>

#include "catena/core/mpi_comm.hpp"
#include "catena/io/atomic_file.hpp"
#include "catena/io/modes_result.hpp"
#include "catena/io/output_error.hpp"
#include "collective_phase.hpp"
#include "hdf5_attributes.hpp"
#include "hdf5_error.hpp"
#include "hdf5_parallel_write.hpp"
#include "mesh_layout.hpp"
#include "row_redistribution.hpp"
#include "xdmf_writer.hpp"

namespace catena::io {
namespace {

namespace fs = std::filesystem;

constexpr const char* kFormat = "catena-modes-1";
constexpr const char* kModesGroup = "/modes";
constexpr const char* kFrequency = "/modes/frequency";
constexpr const char* kEquilibrium = "/modes/equilibrium_positions";

std::string shape_name(std::size_t mode) { return "/modes/shape_" + std::to_string(mode + 1); }

// Collective. /mesh from the model, which every rank holds: each rank its balanced block.
void write_mesh(const ParallelHdf5File& file, const model::Model& model) {
  const int rank = mpi_rank(file.comm()), size = mpi_size(file.comm());
  const auto n_nodes = static_cast<std::int64_t>(model.nodes.size());
  const auto n_elements = static_cast<std::int64_t>(model.elements.size());
  const RowBlock nb = balanced_block(n_nodes, rank, size);
  const RowBlock eb = balanced_block(n_elements, rank, size);
  std::vector<std::int64_t> ids, element_ids, element_nodes;
  std::vector<double> reference;
  for (std::int64_t k = nb.begin; k < nb.begin + nb.count; ++k) {
    const model::Node& node = model.nodes[static_cast<std::size_t>(k)];
    ids.push_back(node.id);
    reference.insert(reference.end(), {node.position.x(), node.position.y(), node.position.z()});
  }
  for (std::int64_t k = eb.begin; k < eb.begin + eb.count; ++k) {
    const model::ElementDesc& e = model.elements[static_cast<std::size_t>(k)];
    element_ids.push_back(e.id);
    element_nodes.insert(element_nodes.end(), {e.nodes.front(), e.nodes.back()});
  }
  create_group(file, mesh_layout::group);
  write_block_dataset<std::int64_t>(file, {mesh_layout::node_ids, n_nodes, 1}, nb, ids);
  write_block_dataset<double>(file, {mesh_layout::node_positions, n_nodes, 3, "m"}, nb, reference);
  write_block_dataset<std::int64_t>(file, {mesh_layout::element_ids, n_elements, 1}, eb,
                                    element_ids);
  write_block_dataset<std::int64_t>(
      file, {mesh_layout::element_nodes, n_elements, mesh_layout::nodes_per_element}, eb,
      element_nodes);
}

// The XDMF: a temporal collection whose step k is mode k, on the equilibrium's geometry.
std::string modes_xdmf(const std::string& h5, std::int64_t n_nodes, std::int64_t n_elements,
                       const std::vector<double>& frequency) {
  const std::string file = xml_escaped(h5);
  std::ostringstream x;
  x << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n  <Domain>\n"
    << "    <Grid Name=\"modes\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (std::size_t k = 0; k < frequency.size(); ++k) {
    x << "      <Grid Name=\"mode " << k + 1 << " (" << frequency[k]
      << " Hz)\" GridType=\"Uniform\">\n"
      << "        <Time Value=\"" << k + 1 << "\"/>\n"
      << "        <Topology TopologyType=\"Polyline\" NodesPerElement=\"2\" NumberOfElements=\""
      << n_elements << "\">\n          <DataItem Dimensions=\"" << n_elements
      << " 2\" NumberType=\"Int\" Precision=\"8\" Format=\"HDF\">" << file << ':'
      << mesh_layout::element_nodes << "</DataItem>\n        </Topology>\n"
      << "        <Geometry GeometryType=\"XYZ\">\n          <DataItem Dimensions=\"" << n_nodes
      << " 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << file << ':' << kEquilibrium
      << "</DataItem>\n        </Geometry>\n"
      << "        <Attribute Name=\"shape\" AttributeType=\"Vector\" Center=\"Node\">\n"
      << "          <DataItem Dimensions=\"" << n_nodes
      << " 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << file << ':' << shape_name(k)
      << "</DataItem>\n        </Attribute>\n      </Grid>\n";
  }
  x << "    </Grid>\n  </Domain>\n</Xdmf>\n";
  return x.str();
}

void write_atomically(MPI_Comm comm, const fs::path& path, const model::Model& model,
                      const ModesResult& r, const RunInfo& info) {
  const bool root = mpi_rank(comm) == 0;
  const fs::path xdmf = xdmf_path_for(path);
  CollectiveTemporary h5_temporary(comm, path), xdmf_temporary(comm, xdmf);
  const auto n_nodes = static_cast<std::int64_t>(model.nodes.size());
  const auto n_modes = static_cast<std::int64_t>(r.frequency.size());
  {
    ParallelHdf5File file = run_collective_phase(
        comm, [&] { return ParallelHdf5File(comm, h5_temporary.path.string()); });
    write_mesh(file, model);
    const RowRedistribution rows(comm, n_nodes, r.owned_nodes, "ModesResult::owned_nodes");
    create_group(file, kModesGroup);
    std::vector<double> frequency;
    if (root) frequency = r.frequency;
    write_block_dataset<double>(file, {kFrequency, n_modes, 1, "Hz"},
                                RowBlock{0, root ? n_modes : 0}, frequency);
    write_block_dataset<double>(file, {kEquilibrium, n_nodes, 3, "m"}, rows.block(),
                                rows.to_block(r.positions, 3));
    for (std::size_t k = 0; k < r.shapes.size(); ++k) {
      const std::string name = shape_name(k);
      write_block_dataset<double>(file, {name.c_str(), n_nodes, 3, "m/sqrt(kg)"}, rows.block(),
                                  rows.to_block(r.shapes[k], 3));
    }
    run_output_phase(comm, [&] {
      const AttributeTarget root_group{file.id(), file.path()};
      write_string_attribute(root_group, "format", kFormat);
      write_string_attribute(root_group, "scene_text", model.source_text);
      write_string_attribute(root_group, "scene_file", model.source_file);
      write_string_attribute(root_group, "code_version", info.code_version);
      write_string_attribute(root_group, "command_line", info.command_line);
      write_int64_attribute(root_group, "n_ranks", info.n_ranks);
      write_int64_attribute(root_group, "n_dofs", info.n_dofs);
    });
    run_collective_phase(comm, [&] { file.close(); });
  }
  fsync_once_per_node(comm, h5_temporary.path);
  run_collective_phase(comm, [&] {
    if (!root) return;
    write_file_durably(xdmf_temporary.path,
                       modes_xdmf(path.filename().string(), n_nodes,
                                  static_cast<std::int64_t>(model.elements.size()), r.frequency));
    publish_with_xdmf(*h5_temporary.owner, path, *xdmf_temporary.owner, xdmf);
  });
}

}  // namespace

void write_modes(MPI_Comm comm, const std::string& path, const model::Model& model,
                 const ModesResult& result, const RunInfo& info) {
  write_result_file(path, [&] { write_atomically(comm, fs::path(path), model, result, info); });
}

}  // namespace catena::io
